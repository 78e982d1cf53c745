// Numbered output files (screenshot-0001.png, record-0002/) that two processes writing to the
// same folder never share: the name is claimed by creating it exclusively (O_EXCL, mkdir), so
// a second instance that looks at the same moment gets the next number.
#pragma once
#include <string>

namespace sn::io {

// Creates `dir` (and parents) and an empty file dir/stem-NNNN.ext with the first free number
// (from 1, four digits or more); returns its path. The caller writes over it. Throws naming the
// folder and the cause when none can be created.
std::string claim_numbered_file(const std::string& dir, const std::string& stem, const std::string& ext);
// The same for a folder dir/stem-NNNN.
std::string claim_numbered_dir(const std::string& dir, const std::string& stem);

}  // namespace sn::io
