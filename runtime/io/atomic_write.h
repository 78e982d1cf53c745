// Writing a whole file so that it is never half-written: the bytes go to a temporary file beside
// the target, every write, the flush, fsync and close are checked, then the temporary is renamed
// over the target (a symbolic link's target: the link stays; a dangling link's target is made).
// The new file keeps the old one's permissions (and owner, where the writer may give it); a new
// one gets 0666 less the umask. On any failure the old file is untouched, the temporary is removed
// and the error names the path and the cause ("No space left on device", ...).
//
// What is not a regular file — a FIFO, a character device, a pipe or terminal behind /dev/stdout —
// has no old contents to keep and is written into as it is (no temporary, never replaced). A path
// that leads to one of this process's descriptors (/dev/stdout, /dev/fd/N, /proc/self/fd/N) is
// written through it, where it stands, as print() writes, whatever it is (a file stdout is sent
// to, a socket); another process's open file (/proc/PID/fd/N) is appended to. A folder is an
// error.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sn::io {

// Creates missing parent folders. `what` starts the message: "cannot write <what> '<path>': ...".
void write_file_atomic(const std::string& path, const std::string& bytes, const std::string& what = "file");

// Many files (path, bytes) at once, each as write_file_atomic writes one, but flushed to the disk
// together: every temporary file is written, then one syncfs per file system, then each is
// renamed. An experiment's hundreds of run records cost one flush instead of one each (360
// records of 3 KB: 0.07-0.08 s, against 0.12-0.15 s with an fsync each; docs/performance.md).
// A failure before the renames leaves every old file as it was; one during them (rare: the
// folder removed meanwhile) leaves the files before it new and the rest old, each whole. Streams
// and devices are written at their turn among the renames.
// `before_renames`, when given, runs once every temporary file is written and flushed (a dataset
// export keeps its old arrays under other names there, data/dataset_file.cpp).
void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& files, const std::string& what = "file",
                        const std::function<void()>& before_renames = {});

// The file a write to `path` goes to: symbolic links followed (a relative one from the link's
// folder) to the path they end at, which need not exist. A link in /proc's fd folders is not
// followed (its target is an open file, not a path), nor one past 40 in a row (a loop): the path
// where following stopped is returned, and opening it tells the rest.
std::string through_links(const std::string& path);

// Removes from `dir` the temporary files a killed writer left (".NAME.tmpDIGITS", as the functions
// above name them: created anew with random digits, NAME cut short where the whole would pass
// NAME_MAX) that are older than `min_age_seconds`: a live writer's lasts milliseconds, and
// another process (a shard of the same sweep) may be writing beside us. With `names`, only the
// temporaries of files so named (a dataset export's three). Returns how many. Nothing happens
// when `dir` is not a folder.
int remove_stale_temporaries(const std::string& dir, double min_age_seconds = 60,
                             const std::vector<std::string>& names = {});

}  // namespace sn::io
