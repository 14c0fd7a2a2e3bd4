// The one way pgamesh writes a file: atomically. The bytes go to a new temporary file in the same
// folder, which is flushed to disk and then renamed over `path`; a program killed or failing
// mid-write leaves the old file (or none), never a truncated one.
#pragma once

#include <string>
#include <string_view>

namespace pgamesh {

// Writes `bytes` to `path`, replacing any file there in one step (rename(2) within one folder).
// A new file gets the mode 0666 less the umask, as with fopen. Throws std::runtime_error naming
// the path when it cannot be written; the temporary file is then removed.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace pgamesh
