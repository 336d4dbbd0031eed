// Writing output files so that a failed or interrupted write never leaves a partial file that
// looks complete: the bytes go to "<path>.partial", which is renamed into place once closed.
#pragma once

#include <filesystem>
#include <string_view>

namespace engine::io {

// Throws std::runtime_error naming the path when it cannot be written (missing or read-only
// folder, disk full); the temporary file is removed in that case.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Throws std::runtime_error with one clear line when `folder` cannot be created or written to.
void ensure_writable_folder(const std::filesystem::path& folder);

// Whether a file can be created in the existing `folder`: a probe of a name no other file has
// (created exclusively, then removed), so no file of the user's is touched. access() is not
// enough: /proc and the like pass it for root.
bool folder_is_writable(const std::filesystem::path& folder);

}  // namespace engine::io
