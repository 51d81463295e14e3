#pragma once
// Where results go, checked before the work that fills them: a path that cannot take them is
// an InputError naming it at once, not a filesystem error after an hour's run.

#include <filesystem>

namespace caskdem {

// Creates the directory (and its parents); an InputError if it is a file, cannot be created,
// or cannot be written.
void prepare_output_directory(const std::filesystem::path& directory);

// Creates the file's directory; an InputError if the path is a directory or its directory
// cannot be created or written. The file itself is left alone (a resumed run reads it).
void prepare_output_file(const std::filesystem::path& file);

}  // namespace caskdem
