// Networks on disk. Format version 1, all numbers little-endian:
//
//   offset 0   8 bytes  magic "snmlp\r\n\x1a" (the \r\n and ^Z catch text-mode mangling)
//          8   u32      format version (1)
//         12   u32      payload size in bytes
//         16   u64      FNV-1a 64 checksum of the payload
//         24   payload:
//     u32 inputs, u32 outputs, u32 hidden count, u32 width per hidden layer
//     str activation, f64 slope, str output activation, str colour space  (str = u32 length + bytes)
//     u32 input name count, str per name
//     u64 trained steps
//     u64 parameter count, f32 per parameter (the flat layout of nn/mlp_spec.h)
//     u32 best epoch (0 = no best snapshot); when > 0: f64 best validation MSE, f32 x parameter count
//   then optional sections, each a str tag and its data (a network that needs none ends before
//   them, as files before them did):
//     "conditions" (a conditioned network): u32 count, per condition str name, f64 min, f64 max,
//     f64 value
//     "encodings" (a network that encodes inputs, nn/encoding.h): u32 count, per encoded input
//     str input name, u32 first column, u32 width, str encoding, u32 count (bands, bins or
//     degree), u8 include_input, f64 range min, f64 range max
//     "entries": u32 count, per entry str key, str value ("omega", "alpha": an activation's
//     parameter, written when the network uses it; "activation NAME glsl" / "activation NAME
//     grad": a user's activation, by definition)
//
// Saving writes a temporary file beside the target and renames it over the target, so a
// failed save never leaves a half-written checkpoint. Loading checks magic, version, size and
// checksum and names what is wrong.
#pragma once
#include <string>

#include "nn/mlp.h"

namespace sn::nn {

constexpr unsigned kCheckpointVersion = 1;

void save_checkpoint(const Mlp& net, const std::string& path);
Mlp load_checkpoint(const std::string& path);

}  // namespace sn::nn
