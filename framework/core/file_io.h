// Result files that an interruption cannot leave half-written (brief: "nothing is lost"): the
// text goes to a temporary file beside the target, which then replaces the target in one
// rename (atomic on POSIX file systems).
#pragma once

#include <string>

namespace rearm {

// Writes `text` to `path` atomically, creating parent directories. Throws rearm::Error naming the
// path and the system's reason when it cannot.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace rearm
