#include "io/hdf5_file.h"

#include <unistd.h>

#include "core/error.h"
#include "core/text.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include <boost/crc.hpp>

namespace caskdem::hdf5 {

namespace {

// Silence HDF5's own error stack printing; failures are reported by exceptions instead.
void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

Handle dataspace_1d(std::size_t n) {
  const hsize_t dims[1] = {static_cast<hsize_t>(n)};
  return Handle(H5Screate_simple(1, dims, nullptr), H5Sclose);
}

Handle string_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

}  // namespace

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0 && close_) close_(id_);
    id_ = other.id_;
    close_ = other.close_;
    other.id_ = -1;
  }
  return *this;
}

Handle::~Handle() {
  if (id_ >= 0 && close_) close_(id_);
}

void Group::fail(const std::string& what) const {
  throw std::runtime_error(file_.string() + ": HDF5 " + what + " in " + path_);
}

Group Group::group(const std::string& name) {
  Handle g(H5Gcreate2(id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail("cannot create group " + name);
  return Group(std::move(g), path_ == "/" ? "/" + name : path_ + "/" + name, file_);
}

Group Group::open_group(const std::string& name) const {
  Handle g(H5Gopen2(id(), name.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail("no group " + name);
  return Group(std::move(g), path_ == "/" ? "/" + name : path_ + "/" + name, file_);
}

bool Group::has(const std::string& name) const { return H5Lexists(id(), name.c_str(), H5P_DEFAULT) > 0; }

void Group::remove(const std::string& name) {
  if (has(name) && H5Ldelete(id(), name.c_str(), H5P_DEFAULT) < 0) fail("cannot remove " + name);
}

std::vector<std::string> Group::member_names() const {
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  if (H5Literate(id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0) fail("cannot list the members");
  return names;
}

void Group::write(const std::string& name, const std::vector<double>& values, const std::string& units) {
  write_matrix(name, values, values.size(), 1, units);
}

void Group::write_matrix(const std::string& name, const std::vector<double>& values, std::size_t rows,
                         std::size_t columns, const std::string& units) {
  const hsize_t dims2[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
  Handle space = columns == 1 ? dataspace_1d(rows) : Handle(H5Screate_simple(2, dims2, nullptr), H5Sclose);
  Handle set(H5Dcreate2(id(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail("cannot create dataset " + name);
  if (!values.empty() && H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    fail("cannot write dataset " + name);
  }
  label_units(std::move(set), name, units);
}

void Group::label_units(Handle set, const std::string& name, const std::string& units) {
  if (units.empty()) fail("dataset " + name + " written without a unit");
  Group dataset(std::move(set), path_ + "/" + name, file_);
  dataset.attribute("units", units);
}

void Group::write(const std::string& name, const std::vector<std::int64_t>& values, const std::string& units) {
  Handle space = dataspace_1d(values.size());
  Handle set(H5Dcreate2(id(), name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail("cannot create dataset " + name);
  if (!values.empty() && H5Dwrite(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    fail("cannot write dataset " + name);
  }
  label_units(std::move(set), name, units);
}

void Group::write(const std::string& name, const std::vector<std::uint8_t>& values, const std::string& units) {
  Handle space = dataspace_1d(values.size());
  Handle set(H5Dcreate2(id(), name.c_str(), H5T_STD_U8LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail("cannot create dataset " + name);
  if (!values.empty() && H5Dwrite(set.get(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    fail("cannot write dataset " + name);
  }
  label_units(std::move(set), name, units);
}

void Group::write_strings(const std::string& name, const std::vector<std::string>& values) {
  Handle space = dataspace_1d(values.size());
  Handle type = string_type();
  Handle set(H5Dcreate2(id(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail("cannot create dataset " + name);
  std::vector<const char*> pointers;
  for (const std::string& v : values) pointers.push_back(v.c_str());
  if (!values.empty() && H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
    fail("cannot write dataset " + name);
  }
}

namespace {
template <class T>
std::vector<T> read_dataset(hid_t group, const std::string& name, hid_t memory_type, const std::string& where) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw std::runtime_error(where + ": no dataset " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose);
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  std::vector<T> values(static_cast<std::size_t>(count));
  if (count > 0 && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw std::runtime_error(where + ": cannot read dataset " + name);
  }
  return values;
}
}  // namespace

std::vector<double> Group::read_doubles(const std::string& name) const {
  return read_dataset<double>(id(), name, H5T_NATIVE_DOUBLE, file_.string() + ":" + path_);
}
std::vector<std::int64_t> Group::read_integers(const std::string& name) const {
  return read_dataset<std::int64_t>(id(), name, H5T_NATIVE_INT64, file_.string() + ":" + path_);
}
std::vector<std::uint8_t> Group::read_bytes(const std::string& name) const {
  return read_dataset<std::uint8_t>(id(), name, H5T_NATIVE_UINT8, file_.string() + ":" + path_);
}

std::vector<std::string> Group::read_strings(const std::string& name) const {
  Handle set(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail("no dataset " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose);
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  Handle type = string_type();
  std::vector<char*> pointers(static_cast<std::size_t>(count), nullptr);
  if (count > 0 && H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
    fail("cannot read dataset " + name);
  }
  std::vector<std::string> values;
  for (char* p : pointers) values.emplace_back(p ? p : "");
  if (count > 0) H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, pointers.data());
  return values;
}

void Group::attribute(const std::string& name, double value) {
  if (H5Aexists(id(), name.c_str()) > 0) H5Adelete(id(), name.c_str());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle a(H5Acreate2(id(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail("cannot write attribute " + name);
}

void Group::attribute(const std::string& name, std::int64_t value) {
  if (H5Aexists(id(), name.c_str()) > 0) H5Adelete(id(), name.c_str());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle a(H5Acreate2(id(), name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_INT64, &value) < 0) fail("cannot write attribute " + name);
}

void Group::attribute(const std::string& name, const std::string& value) {
  if (H5Aexists(id(), name.c_str()) > 0) H5Adelete(id(), name.c_str());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle type = string_type();
  Handle a(H5Acreate2(id(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const char* text = value.c_str();
  if (!a.valid() || H5Awrite(a.get(), type.get(), &text) < 0) fail("cannot write attribute " + name);
}

bool Group::has_attribute(const std::string& name) const { return H5Aexists(id(), name.c_str()) > 0; }

double Group::double_attribute(const std::string& name) const {
  Handle a(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  double value = 0.0;
  if (!a.valid() || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail("no attribute " + name);
  return value;
}

std::int64_t Group::integer_attribute(const std::string& name) const {
  Handle a(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  std::int64_t value = 0;
  if (!a.valid() || H5Aread(a.get(), H5T_NATIVE_INT64, &value) < 0) fail("no attribute " + name);
  return value;
}

std::string Group::string_attribute(const std::string& name) const {
  Handle a(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.valid()) fail("no attribute " + name);
  Handle type = string_type();
  char* text = nullptr;
  if (H5Aread(a.get(), type.get(), &text) < 0) fail("cannot read attribute " + name);
  std::string value = text ? text : "";
  H5free_memory(text);
  return value;
}

Group create_file(const std::filesystem::path& file) {
  quiet();
  Handle f(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!f.valid()) throw std::runtime_error(file.string() + ": cannot create the HDF5 file");
  Handle root(H5Gopen2(f.get(), "/", H5P_DEFAULT), H5Gclose);
  // The root group keeps the file open (HDF5 closes a file when its last object closes).
  return Group(std::move(root), "/", file);
}

Group open_file(const std::filesystem::path& file) {
  require_regular_file(file, "a caskdem result file (HDF5)", std::numeric_limits<std::uintmax_t>::max());
  quiet();
  Handle f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!f.valid()) throw std::runtime_error(file.string() + ": cannot open as an HDF5 file");
  Handle root(H5Gopen2(f.get(), "/", H5P_DEFAULT), H5Gclose);
  return Group(std::move(root), "/", file);
}

namespace {

constexpr std::string_view kSealMagic = "caskdem seal crc32 ";

// CRC-32 and length of the file's bytes after the user block.
std::pair<std::uint32_t, std::uintmax_t> sealed_content(std::ifstream& in) {
  boost::crc_32_type crc;
  std::uintmax_t length = 0;
  in.seekg(static_cast<std::streamoff>(kSealBytes));
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    crc.process_bytes(buffer.data(), got);
    length += got;
  }
  return {crc.checksum(), length};
}

}  // namespace

Group create_in_memory(const std::string& name) {
  quiet();
  Handle creation(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (H5Pset_userblock(creation.get(), kSealBytes) < 0 || H5Pset_fapl_core(access.get(), 1 << 20, 0) < 0) {
    throw std::runtime_error(name + ": cannot set up an HDF5 file in memory");
  }
  Handle f(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, creation.get(), access.get()), H5Fclose);
  if (!f.valid()) throw std::runtime_error(name + ": cannot create the HDF5 file in memory");
  Handle root(H5Gopen2(f.get(), "/", H5P_DEFAULT), H5Gclose);
  return Group(std::move(root), "/", name);
}

std::vector<char> file_image(const Group& root) {
  Handle f(H5Iget_file_id(root.id()), H5Fclose);
  if (!f.valid() || H5Fflush(f.get(), H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error("cannot flush the HDF5 file");
  const ssize_t size = H5Fget_file_image(f.get(), nullptr, 0);
  if (size <= 0) throw std::runtime_error("cannot take the HDF5 file's image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(f.get(), image.data(), image.size()) != size) {
    throw std::runtime_error("cannot take the HDF5 file's image");
  }
  return image;
}

void write_sealed(const std::filesystem::path& file, const std::vector<char>& image) {
  boost::crc_32_type crc;
  crc.process_bytes(image.data(), image.size());
  char seal[kSealBytes] = {};
  std::snprintf(seal, sizeof seal, "%s%08x bytes %zu\n", std::string(kSealMagic).c_str(),
                static_cast<unsigned>(crc.checksum()), image.size());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(seal, sizeof seal);
  out.write(image.data(), static_cast<std::streamsize>(image.size()));
  out.close();
  if (!out) throw std::runtime_error(file.string() + ": cannot be written whole (is the disk full?)");
}

Group open_sealed_in_memory(const std::filesystem::path& file, const std::string& expected) {
  check_seal(file, expected);
  quiet();
  std::ifstream in(file, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The image as on disk (seal in the user block, HDF5 after it); HDF5 copies it.
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (H5Pset_fapl_core(access.get(), 1 << 20, 0) < 0 || H5Pset_file_image(access.get(), bytes.data(), bytes.size()) < 0)
    throw std::runtime_error(file.string() + ": cannot set up an HDF5 file in memory");
  // Under a name of its own: HDF5 would take the path for the file on disk if that is open.
  const std::string name = file.string() + ".in-memory";
  Handle f(H5Fopen(name.c_str(), H5F_ACC_RDWR, access.get()), H5Fclose);
  if (!f.valid()) throw InputError(located(file, 0, "cannot be opened as HDF5; expected " + expected));
  Handle root(H5Gopen2(f.get(), "/", H5P_DEFAULT), H5Gclose);
  return Group(std::move(root), "/", file);
}

void replace_sealed(const std::filesystem::path& file, const std::function<std::vector<char>()>& make_image) {
  const std::filesystem::path temporary = file.string() + ".partial-" + std::to_string(::getpid());
  try {
    write_sealed(temporary, make_image());
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(std::string(e.what()) + "; " + file.string() +
                             (std::filesystem::exists(file) ? " is left as it was" : " was not written"));
  }
  std::filesystem::rename(temporary, file);
}

void check_seal(const std::filesystem::path& file, const std::string& expected) {
  require_regular_file(file, expected, std::numeric_limits<std::uintmax_t>::max());
  std::ifstream in(file, std::ios::binary);
  char seal[kSealBytes] = {};
  in.read(seal, sizeof seal);
  const std::string head(seal, strnlen(seal, sizeof seal));
  unsigned stated_crc = 0;
  std::uintmax_t stated_length = 0;
  if (!in || !head.starts_with(kSealMagic) ||
      std::sscanf(head.c_str() + kSealMagic.size(), "%8x bytes %ju", &stated_crc, &stated_length) != 2) {
    throw InputError(located(file, 0, "has no caskdem seal (not written by this version of caskdem, or its start is "
                                      "damaged); expected " + expected));
  }
  in.clear();
  const auto [crc, length] = sealed_content(in);
  if (length != stated_length) {
    throw InputError(located(file, 0, "is " + std::to_string(length + kSealBytes) + " bytes where its seal says " +
                                          std::to_string(stated_length + kSealBytes) + " (cut short, or appended to); "
                                          "expected " + expected + " as caskdem wrote it"));
  }
  if (crc != stated_crc) {
    throw InputError(located(file, 0, "its bytes do not match its seal's checksum (the file is damaged); expected " +
                                          expected + " as caskdem wrote it"));
  }
}

}  // namespace caskdem::hdf5
