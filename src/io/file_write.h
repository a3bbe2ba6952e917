// The one checked way every output file is written (images, JSON, caches): a full disk, a closed
// pipe or a read-only target must fail the command, and a buffered write only fails at flush or
// close, so both are checked.
#pragma once
#include <string>
#include <string_view>

namespace penumbra {

// Writes `bytes` to `path` (created or truncated). Throws std::runtime_error with one line naming
// the file and the system's reason when opening, writing, flushing or closing fails.
void writeFileChecked(const std::string& path, std::string_view bytes);

// `text` followed by a newline, through writeFileChecked (JSON results, cache metadata).
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace penumbra
