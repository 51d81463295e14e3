#pragma once
// A thin RAII layer over the HDF5 C library: files, groups, datasets of doubles and
// integers, and attributes. Every failure throws std::runtime_error naming the file and
// the object. Readers need nothing but h5py: datasets are plain arrays with a "units"
// attribute where they have a unit.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <hdf5.h>

namespace caskdem::hdf5 {

// Owns one HDF5 identifier and closes it with the right function.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle();
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

class Group {
 public:
  Group(Handle handle, std::string path, std::filesystem::path file)
      : handle_(std::move(handle)), path_(std::move(path)), file_(std::move(file)) {}

  Group group(const std::string& name);         // creates
  Group open_group(const std::string& name) const;
  bool has(const std::string& name) const;
  void remove(const std::string& name);  // a member (group or dataset), if there
  std::vector<std::string> member_names() const;  // groups and datasets, in name order

  // Every numeric dataset states its unit (a UDUNITS string: "m/s", "rad", "1/yr"; "1" for a
  // dimensionless number, a count or a flag), written as its `units` attribute.
  void write(const std::string& name, const std::vector<double>& values, const std::string& units);
  void write(const std::string& name, const std::vector<std::int64_t>& values, const std::string& units);
  void write(const std::string& name, const std::vector<std::uint8_t>& values, const std::string& units);
  // Row-major matrix rows x columns.
  void write_matrix(const std::string& name, const std::vector<double>& values, std::size_t rows, std::size_t columns,
                    const std::string& units);
  void write_strings(const std::string& name, const std::vector<std::string>& values);

  std::vector<double> read_doubles(const std::string& name) const;
  std::vector<std::int64_t> read_integers(const std::string& name) const;
  std::vector<std::uint8_t> read_bytes(const std::string& name) const;
  std::vector<std::string> read_strings(const std::string& name) const;

  void attribute(const std::string& name, double value);
  void attribute(const std::string& name, std::int64_t value);
  void attribute(const std::string& name, const std::string& value);
  double double_attribute(const std::string& name) const;
  std::int64_t integer_attribute(const std::string& name) const;
  std::string string_attribute(const std::string& name) const;
  bool has_attribute(const std::string& name) const;

  hid_t id() const { return handle_.get(); }
  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail(const std::string& what) const;
  void label_units(Handle set, const std::string& name, const std::string& units);
  Handle handle_;
  std::string path_;
  std::filesystem::path file_;
};

// Creates (truncating) or opens a file; the root group is "/".
Group create_file(const std::filesystem::path& file);
Group open_file(const std::filesystem::path& file);  // read-only

// A sealed file is built in memory (create_in_memory) and written by write_sealed with a
// seal in its user block (kSealBytes, which HDF5 and h5py skip): the CRC-32 and length of
// everything after it. Every write is then checked (HDF5 does not report a failed flush at
// close, and on a full disk left a short file that it still opened). check_seal refuses
// (InputError naming the file) a file without a seal or whose bytes no longer match it,
// before HDF5 parses any of it: a file cut short or with flipped bits is refused whole, where
// HDF5 itself may read damaged values or hang on a damaged heap.
inline constexpr std::size_t kSealBytes = 512;
Group create_in_memory(const std::string& name);
std::vector<char> file_image(const Group& root);  // the file after its user block
void write_sealed(const std::filesystem::path& file, const std::vector<char>& image);
// Replaces `file` by the sealed image `make_image` builds, written to a temporary file beside
// it and renamed over it, so the file on disk is always whole. If building or writing fails,
// the temporary file is removed and the previous file is left as it was; the error (a
// std::runtime_error) says so.
void replace_sealed(const std::filesystem::path& file, const std::function<std::vector<char>()>& make_image);
void check_seal(const std::filesystem::path& file, const std::string& expected);
// A sealed file, its seal checked, opened in memory to be added to; write it back with
// file_image and write_sealed (to a temporary file renamed over it, as every sealed write).
Group open_sealed_in_memory(const std::filesystem::path& file, const std::string& expected);

}  // namespace caskdem::hdf5
