#include "io/output_paths.h"

#include <system_error>

#include <unistd.h>

#include "core/error.h"

namespace caskdem {

void prepare_output_directory(const std::filesystem::path& directory) {
  std::error_code error;
  if (std::filesystem::exists(directory, error) && !std::filesystem::is_directory(directory, error))
    throw InputError(directory.string() + ": is a file; expected a directory for the results (or a new path)");
  std::filesystem::create_directories(directory, error);
  if (error) throw InputError(directory.string() + ": cannot be created as a directory for the results (" + error.message() + ")");
  if (::access(directory.c_str(), W_OK) != 0)
    throw InputError(directory.string() + ": cannot be written; expected a writable directory for the results");
}

void prepare_output_file(const std::filesystem::path& file) {
  std::error_code error;
  if (std::filesystem::is_directory(file, error))
    throw InputError(file.string() + ": is a directory; expected a file name for the results");
  prepare_output_directory(file.has_parent_path() ? file.parent_path() : std::filesystem::path("."));
}

}  // namespace caskdem
