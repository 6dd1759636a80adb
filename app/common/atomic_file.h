#pragma once
// Small whole files (cost records, study results, emitted job lists) written so that a reader
// never sees half a file: the text goes to a temporary file beside the target, is flushed, and
// replaces the target by a rename. An interrupted write leaves the old file. Any thread.

#include <string>

namespace grainlab {

/// Writes `text` to `path` atomically; throws std::runtime_error naming the file and the cause.
void writeFileAtomically(const std::string& path, const std::string& text);

/// The whole text of `path`; throws std::runtime_error naming the file when it cannot be read.
std::string readWholeFile(const std::string& path);

} // namespace grainlab
