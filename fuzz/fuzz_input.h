#pragma once
// The fuzz targets hand caskdem's readers a file, as users do: the fuzzer's bytes are written
// to a file of this process (readers take paths, and the checks before opening are part of
// what is tested). An InputError is the readers' one answer to bad input; any other
// exception escaping, a crash, a sanitizer report or a hang is a finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "core/error.h"

namespace caskdem::fuzz {

// A directory of this process under the system's temporary directory, made once.
inline const std::filesystem::path& work_directory() {
  static const std::filesystem::path directory = [] {
    const auto d = std::filesystem::temp_directory_path() / ("caskdem-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return directory;
}

// The bytes as the file `name` in the work directory.
inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const auto file = work_directory() / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  return file;
}

// Runs `read`; an InputError is a refusal (fine), anything else aborts with what escaped.
template <class F>
void expect_refusal_or_success(F&& read) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    std::cerr << "an exception other than InputError escaped: " << e.what() << "\n";
    std::abort();
  }
}

}  // namespace caskdem::fuzz
