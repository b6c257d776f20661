#include "hdf5_file.hpp"

#include <stdexcept>

namespace impact::postprocess::hdf5 {

namespace {

// HDF5 prints its error stack on stderr by default; the callers report errors themselves.
void silence_hdf5() {
  static const bool silenced = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)silenced;
}

herr_t close_attribute(hid_t id) {
  return H5Aclose(id);
}
herr_t close_dataset(hid_t id) {
  return H5Dclose(id);
}
herr_t close_dataspace(hid_t id) {
  return H5Sclose(id);
}
herr_t close_datatype(hid_t id) {
  return H5Tclose(id);
}
herr_t close_file(hid_t id) {
  return H5Fclose(id);
}

Handle check(hid_t id, herr_t (*close)(hid_t), const std::string& what) {
  if (id < 0) throw std::runtime_error(what);
  return Handle(id, close);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error(what);
}

// A scalar attribute read as text (string types) or as a number (integer and float types).
struct AttributeValue {
  std::optional<std::string> text;
  std::optional<double> number;
};

AttributeValue read_attribute(hid_t attribute) {
  AttributeValue value;
  const Handle space(H5Aget_space(attribute), close_dataspace);
  if (!space.valid() || H5Sget_simple_extent_npoints(space.id()) != 1) return value;
  const Handle type(H5Aget_type(attribute), close_datatype);
  if (!type.valid()) return value;
  switch (H5Tget_class(type.id())) {
    case H5T_STRING:
      if (H5Tis_variable_str(type.id()) > 0) {
        const Handle memory_type(H5Tcopy(H5T_C_S1), close_datatype);
        H5Tset_size(memory_type.id(), H5T_VARIABLE);
        H5Tset_cset(memory_type.id(), H5Tget_cset(type.id()));
        char* text = nullptr;
        if (H5Aread(attribute, memory_type.id(), &text) >= 0 && text != nullptr) {
          value.text = std::string(text);
          H5free_memory(text);
        }
      } else {
        const std::size_t size = H5Tget_size(type.id());
        std::string text(size, '\0');
        const Handle memory_type(H5Tcopy(type.id()), close_datatype);
        if (H5Aread(attribute, memory_type.id(), text.data()) >= 0)
          value.text = text.substr(0, text.find('\0'));
      }
      break;
    case H5T_INTEGER:
    case H5T_FLOAT: {
      double number = 0;
      if (H5Aread(attribute, H5T_NATIVE_DOUBLE, &number) >= 0) value.number = number;
      break;
    }
    default:
      break;
  }
  return value;
}

struct AttributeMaps {
  std::map<std::string, std::string>* text;
  std::map<std::string, double>* numbers;
};

herr_t collect_attribute(hid_t location, const char* name, const H5A_info_t*, void* data) {
  auto* maps = static_cast<AttributeMaps*>(data);
  const Handle attribute(H5Aopen(location, name, H5P_DEFAULT), close_attribute);
  if (!attribute.valid()) return 0;
  const AttributeValue value = read_attribute(attribute.id());
  if (value.text) (*maps->text)[name] = *value.text;
  if (value.number) (*maps->numbers)[name] = *value.number;
  return 0;
}

void write_string_attribute(hid_t location, const std::string& name, const std::string& value) {
  // Variable-length UTF-8, as deal.II's HDF5 wrappers write strings.
  const Handle type = check(H5Tcopy(H5T_C_S1), close_datatype, "cannot create a string type");
  H5Tset_size(type.id(), H5T_VARIABLE);
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  const Handle space = check(H5Screate(H5S_SCALAR), close_dataspace, "cannot create a dataspace");
  const Handle attribute =
      check(H5Acreate2(location, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
            close_attribute, "cannot create the attribute '" + name + "'");
  const char* text = value.c_str();
  check(H5Awrite(attribute.id(), type.id(), &text), "cannot write the attribute '" + name + "'");
}

} // namespace

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

File File::open_read_only(const std::string& path) {
  silence_hdf5();
  if (H5Fis_hdf5(path.c_str()) <= 0) throw std::runtime_error("it is not an HDF5 file");
  return File(
      check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), close_file, "HDF5 cannot open it"));
}

File File::create(const std::string& path) {
  silence_hdf5();
  return File(check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), close_file,
                    "HDF5 cannot create '" + path + "'"));
}

bool File::has_dataset(const std::string& name) const {
  if (H5Lexists(file_.id(), name.c_str(), H5P_DEFAULT) <= 0) return false;
  const Handle dataset(H5Dopen2(file_.id(), name.c_str(), H5P_DEFAULT), close_dataset);
  return dataset.valid();
}

std::vector<double> File::read_dataset(const std::string& name) const {
  const Handle dataset = check(H5Dopen2(file_.id(), name.c_str(), H5P_DEFAULT), close_dataset,
                               "the dataset '" + name + "' cannot be opened");
  const Handle space = check(H5Dget_space(dataset.id()), close_dataspace,
                             "the dataset '" + name + "' has no dataspace");
  if (H5Sget_simple_extent_ndims(space.id()) != 1)
    throw std::runtime_error("the dataset '" + name + "' is not one-dimensional");
  const Handle type =
      check(H5Dget_type(dataset.id()), close_datatype, "the dataset '" + name + "' has no type");
  const H5T_class_t type_class = H5Tget_class(type.id());
  if (type_class != H5T_FLOAT && type_class != H5T_INTEGER)
    throw std::runtime_error("the dataset '" + name + "' is not numeric");
  hsize_t size = 0;
  H5Sget_simple_extent_dims(space.id(), &size, nullptr);
  std::vector<double> values(size);
  if (size > 0)
    check(H5Dread(dataset.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "the dataset '" + name + "' cannot be read");
  return values;
}

std::optional<std::string> File::dataset_string_attribute(const std::string& dataset_name,
                                                          const std::string& name) const {
  const Handle dataset(H5Dopen2(file_.id(), dataset_name.c_str(), H5P_DEFAULT), close_dataset);
  if (!dataset.valid() || H5Aexists(dataset.id(), name.c_str()) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen(dataset.id(), name.c_str(), H5P_DEFAULT), close_attribute);
  if (!attribute.valid()) return std::nullopt;
  return read_attribute(attribute.id()).text;
}

void File::read_root_attributes(std::map<std::string, std::string>& text,
                                std::map<std::string, double>& numbers) const {
  AttributeMaps maps{&text, &numbers};
  hsize_t index = 0;
  H5Aiterate2(file_.id(), H5_INDEX_NAME, H5_ITER_NATIVE, &index, collect_attribute, &maps);
}

void File::write_dataset(const std::string& name, const std::vector<double>& values,
                         const std::string& unit, const std::string& description) {
  const hsize_t size = values.size();
  const Handle space =
      check(H5Screate_simple(1, &size, nullptr), close_dataspace, "cannot create a dataspace");
  const Handle dataset = check(H5Dcreate2(file_.id(), name.c_str(), H5T_IEEE_F64LE, space.id(),
                                          H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                               close_dataset, "cannot create the dataset '" + name + "'");
  check(H5Dwrite(dataset.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
        "cannot write the dataset '" + name + "'");
  write_string_attribute(dataset.id(), "unit", unit);
  write_string_attribute(dataset.id(), "description", description);
}

void File::write_attribute(const std::string& name, const std::string& value) {
  write_string_attribute(file_.id(), name, value);
}

void File::write_attribute(const std::string& name, double value) {
  const Handle space = check(H5Screate(H5S_SCALAR), close_dataspace, "cannot create a dataspace");
  const Handle attribute = check(H5Acreate2(file_.id(), name.c_str(), H5T_IEEE_F64LE, space.id(),
                                            H5P_DEFAULT, H5P_DEFAULT),
                                 close_attribute, "cannot create the attribute '" + name + "'");
  check(H5Awrite(attribute.id(), H5T_NATIVE_DOUBLE, &value),
        "cannot write the attribute '" + name + "'");
}

} // namespace impact::postprocess::hdf5
