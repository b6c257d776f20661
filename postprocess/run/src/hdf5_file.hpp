#pragma once
// A minimal RAII layer over the HDF5 C API for the run files: 1-D double datasets and
// scalar attributes (double, or string of variable or fixed length). Errors are
// std::runtime_error with a sentence; HDF5's own error stack printing is switched off.

#include <hdf5.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace impact::postprocess::hdf5 {

/// Owns one HDF5 identifier and closes it with the matching H5*close.
class Handle {
public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  ~Handle();
  hid_t id() const { return id_; }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

/// An HDF5 file, read-only or newly created (truncating).
class File {
public:
  static File open_read_only(const std::string& path); // throws if not an HDF5 file
  static File create(const std::string& path);

  bool has_dataset(const std::string& name) const;
  /// The 1-D dataset `name` as doubles; throws if it is not 1-D numeric.
  std::vector<double> read_dataset(const std::string& name) const;
  std::optional<std::string> dataset_string_attribute(const std::string& dataset,
                                                      const std::string& attribute) const;

  /// All scalar attributes of the root group, split into text and numbers.
  void read_root_attributes(std::map<std::string, std::string>& text,
                            std::map<std::string, double>& numbers) const;

  void write_dataset(const std::string& name, const std::vector<double>& values,
                     const std::string& unit, const std::string& description);
  void write_attribute(const std::string& name, const std::string& value);
  void write_attribute(const std::string& name, double value);

private:
  explicit File(Handle file) : file_(std::move(file)) {}
  Handle file_;
};

} // namespace impact::postprocess::hdf5
