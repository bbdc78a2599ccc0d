#include "io/hdf5_output.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/output_schema.hpp"

namespace granmc {
namespace {

/// Thrown inside this file on an HDF5 failure; write_hdf5 turns it into std::runtime_error with the path.
struct Hdf5Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The innermost message of HDF5's error stack (e.g. "unable to open file: ... No such file or directory").
std::string hdf5_detail() {
  std::string detail;
  auto take_first = [](unsigned n, const H5E_error2_t* err, void* data) -> herr_t {
    if (n == 0 && err->desc != nullptr) *static_cast<std::string*>(data) = err->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_first, &detail);
  return detail;
}

[[noreturn]] void fail(const std::string& what) {
  const std::string detail = hdf5_detail();
  throw Hdf5Failure(detail.empty() ? what : what + " (" + detail + ")");
}

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

void check_status(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) noexcept : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  [[nodiscard]] hid_t get() const noexcept { return id_; }
  /// Closes now and reports a failure (a file's close is where buffered writes can fail).
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    check_status(close_(id), what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// Silences HDF5's own error printing for the lifetime of the object and restores it afterwards.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Writes objects into one open file, by absolute path, creating intermediate groups as needed.
class Writer {
 public:
  explicit Writer(hid_t file)
      : file_(file), lcpl_(check(H5Pcreate(H5P_LINK_CREATE), "cannot create a property list"), H5Pclose) {
    check_status(H5Pset_create_intermediate_group(lcpl_.get(), 1), "cannot set intermediate group creation");
  }

  void group(const std::string& path, const std::string& description) {
    Handle g(check(H5Gcreate2(file_, path.c_str(), lcpl_.get(), H5P_DEFAULT, H5P_DEFAULT),
                   "cannot create group '" + path + "'"),
             H5Gclose);
    string_attribute(g.get(), path, "description", description);
  }

  /// The one dataset writer: `data` holds prod(dims) values of `memory_type` in row-major order.
  void dataset(const std::string& path, hid_t memory_type, hid_t file_type, const void* data,
               const std::vector<hsize_t>& dims, const std::string& description) {
    Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                       "cannot create dataspace for '" + path + "'"),
                 H5Sclose);
    Handle set(check(H5Dcreate2(file_, path.c_str(), file_type, space.get(), lcpl_.get(), H5P_DEFAULT, H5P_DEFAULT),
                     "cannot create dataset '" + path + "'"),
               H5Dclose);
    bool empty = false;
    for (hsize_t d : dims) empty = empty || d == 0;
    if (!empty)
      check_status(H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                   "cannot write dataset '" + path + "'");
    string_attribute(set.get(), path, "description", description);
  }

  void doubles(const std::string& path, std::span<const double> values, const std::vector<hsize_t>& dims,
               const std::string& description) {
    dataset(path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, values.data(), dims, description);
  }
  void doubles(const std::string& path, std::span<const double> values, const std::string& description) {
    doubles(path, values, {values.size()}, description);
  }
  void uint64s(const std::string& path, std::span<const std::uint64_t> values, const std::vector<hsize_t>& dims,
               const std::string& description) {
    dataset(path, H5T_NATIVE_UINT64, H5T_STD_U64LE, values.data(), dims, description);
  }
  void uint64s(const std::string& path, std::span<const std::uint64_t> values, const std::string& description) {
    uint64s(path, values, {values.size()}, description);
  }

  // Attributes of the object at `path` (a group or dataset; "/" is the root).
  void attribute(const std::string& path, const char* name, const std::string& value) {
    Handle object = open(path);
    string_attribute(object.get(), path, name, value);
  }
  void attribute(const std::string& path, const char* name, double value) {
    scalar_attribute(path, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, &value);
  }
  void attribute(const std::string& path, const char* name, std::int64_t value) {
    scalar_attribute(path, name, H5T_NATIVE_INT64, H5T_STD_I64LE, &value);
  }
  void attribute(const std::string& path, const char* name, std::uint64_t value) {
    scalar_attribute(path, name, H5T_NATIVE_UINT64, H5T_STD_U64LE, &value);
  }

 private:
  Handle open(const std::string& path) {
    return Handle(check(H5Oopen(file_, path.c_str(), H5P_DEFAULT), "cannot open '" + path + "'"), H5Oclose);
  }

  void scalar_attribute(const std::string& path, const char* name, hid_t memory_type, hid_t file_type,
                        const void* value) {
    Handle object = open(path);
    const std::string what = "attribute '" + std::string(name) + "' of '" + path + "'";
    Handle space(check(H5Screate(H5S_SCALAR), "cannot create dataspace for " + what), H5Sclose);
    Handle attr(check(H5Acreate2(object.get(), name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      "cannot create " + what),
                H5Aclose);
    check_status(H5Awrite(attr.get(), memory_type, value), "cannot write " + what);
  }

  /// A variable-length UTF-8 string attribute (h5py reads it as str).
  static void string_attribute(hid_t object, const std::string& path, const char* name, const std::string& value) {
    const std::string what = "attribute '" + std::string(name) + "' of '" + path + "'";
    Handle type(check(H5Tcopy(H5T_C_S1), "cannot create string type for " + what), H5Tclose);
    check_status(H5Tset_size(type.get(), H5T_VARIABLE), "cannot size string type for " + what);
    check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set UTF-8 for " + what);
    Handle space(check(H5Screate(H5S_SCALAR), "cannot create dataspace for " + what), H5Sclose);
    Handle attr(
        check(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), "cannot create " + what),
        H5Aclose);
    const char* text = value.c_str();
    check_status(H5Awrite(attr.get(), type.get(), &text), "cannot write " + what);
  }

  hid_t file_;
  Handle lcpl_;
};

/// The parent group's path and the last name of an absolute path ("/a/b" -> "/a", "b"; "/b" -> "/", "b").
std::pair<std::string, std::string> split_leaf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

std::vector<hsize_t> dims_of(const std::vector<std::size_t>& dims) { return {dims.begin(), dims.end()}; }

/// One record's value at `path` (absolute), stored as its kind says (io/output_schema.hpp).
void write_record(Writer& w, const OutputRecord& record, const std::string& path, const RecordValue& value) {
  const auto [parent, leaf] = split_leaf(path);
  const std::string units = record.units.empty() ? "" : " (" + record.units + ")";
  switch (record.kind) {
    case RecordKind::group:
      w.group(path, record.meaning);
      break;
    case RecordKind::text:
      w.attribute(parent, leaf.c_str(), std::get<std::string>(value));
      break;
    case RecordKind::number:
      w.attribute(parent, leaf.c_str(), std::get<double>(value));
      break;
    case RecordKind::count:
      w.attribute(parent, leaf.c_str(), std::get<std::uint64_t>(value));
      break;
    case RecordKind::flag:
      w.attribute(parent, leaf.c_str(), static_cast<std::int64_t>(std::get<bool>(value)));
      break;
    case RecordKind::numbers:
      w.doubles(path, std::get<std::vector<double>>(value), record.meaning + units);
      break;
    case RecordKind::mean_ci: {
      const MeanCI& m = std::get<MeanCI>(value);
      w.group(path, record.meaning + units);
      w.attribute(path, "mean", m.mean);
      w.attribute(path, "ci", m.ci);
      break;
    }
    case RecordKind::series: {
      const MeanCISeries& m = std::get<MeanCISeries>(value);
      w.group(path, record.meaning + units);
      w.doubles(path + "/mean", m.mean, "replica mean" + units);
      w.doubles(path + "/ci", m.ci, "confidence half-width of the replica mean, lambda_p = 3.2 (001 eq. 31)" + units);
      break;
    }
    case RecordKind::rows: {
      const auto& rows = std::get<ReplicaRows<double>>(value);
      w.doubles(path, rows.values, dims_of(rows.dims), record.meaning + units);
      break;
    }
    case RecordKind::count_rows: {
      const auto& rows = std::get<ReplicaRows<std::uint64_t>>(value);
      w.uint64s(path, rows.values, dims_of(rows.dims), record.meaning + units);
      break;
    }
  }
}

void write_contents(hid_t file, const RunOutput& output) {
  Writer w(file);
  const std::string species_mark = "{species}";
  for (const OutputRecord& record : output_records()) {
    const std::size_t mark = record.path.find(species_mark);
    const std::size_t count = mark == std::string::npos ? 1 : output.report.species.size();
    for (std::size_t i = 0; i < count; ++i) {
      const std::optional<RecordValue> value = record.value(output, i);
      if (!value) continue;
      std::string path = "/" + record.path;
      if (mark != std::string::npos)
        path.replace(mark + 1, species_mark.size(), species_group_name(output.report.species[i].name, i));
      write_record(w, record, path, *value);
    }
  }
}

}  // namespace

void write_hdf5(const std::string& path, const Scene& scene, const RunResult& result, const RunReport& report) {
  const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  const QuietHdf5 quiet;
  try {
    Handle file(check(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "cannot create the file"),
                H5Fclose);
    write_contents(file.get(), RunOutput{scene, result, report});
    file.close("cannot close the file");
  } catch (const Hdf5Failure& e) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write HDF5 output '" + path + "': " + e.what());
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write HDF5 output '" + path + "': cannot rename '" + temporary + "' to it (" +
                             reason + ")");
  }
}

}  // namespace granmc
