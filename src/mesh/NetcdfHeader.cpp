// Walks a netCDF classic header with every count checked against the file's size.
#include "mesh/NetcdfHeader.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "core/Errors.hpp"

namespace choc {

namespace {

constexpr uint32_t kAbsent = 0x00, kDimensionTag = 0x0A, kVariableTag = 0x0B,
                   kAttributeTag = 0x0C;
constexpr uint64_t kMaxName = 256;  // NC_MAX_NAME

// Attributes that the Exodus library reads into fixed-size buffers without checking their
// length (a longer one overwrote its stack: found by fuzzing, confirmed with valgrind).
// Global attributes read as one number:
const std::set<std::string> kScalarGlobalAttributes = {
    "api_version", "api version", "version", "floating_point_word_size",
    "floating point word size", "file_size", "maximum_name_length", "int64_status"};
// Variable attributes read into a char[MAX_STR_LENGTH + 1] (MAX_STR_LENGTH = 32):
const std::set<std::string> kShortTextAttributes = {"elem_type"};
constexpr uint64_t kMaxShortText = 32;

// Bytes of one value of netCDF external type `type` (0 if unknown in this version).
uint64_t typeSize(uint32_t type, int version) {
  static const std::array<uint64_t, 12> sizes = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
  const uint32_t last = version == 5 ? 11 : 6;
  return type >= 1 && type <= last ? sizes[type] : 0;
}

uint64_t padded4(uint64_t n) { return (n + 3) / 4 * 4; }

// a*b, or `cap`+1 when it exceeds cap (no overflow).
uint64_t productCapped(uint64_t a, uint64_t b, uint64_t cap) {
  if (a == 0 || b == 0) return 0;
  return a > cap / b ? cap + 1 : a * b;
}

class HeaderWalk {
 public:
  HeaderWalk(const std::string& path, std::ifstream& in, uint64_t fileBytes)
      : path_(path), in_(in), size_(fileBytes) {}

  void run(int version) {
    version_ = version;
    countBytes_ = version == 5 ? 8 : 4;
    offsetBytes_ = version == 1 ? 4 : 8;
    pos_ = 4;
    in_.seekg(4);
    const uint64_t streaming = version == 5 ? std::numeric_limits<uint64_t>::max() : 0xFFFFFFFFu;
    // A streaming file's record count is unknown (netCDF takes it from the file's size).
    const uint64_t numrecs = unsignedField(countBytes_, "the number of records");
    numrecs_ = numrecs == streaming ? 0 : numrecs;
    readDimensions();
    readAttributes("");
    readVariables();
    // A record holds every record variable's slab, each padded to 4 bytes unless there is
    // only one record variable.
    int recordVariables = 0;
    for (const auto& v : variables_) {
      if (!v.record) continue;
      ++recordVariables;
      recordBytes_ = std::min(size_ + 1, recordBytes_ + padded4(v.bytesPerRecord));
    }
    if (recordVariables == 1)
      for (const auto& v : variables_)
        if (v.record) recordBytes_ = v.bytesPerRecord;
    for (const auto& v : variables_) checkExtent(v);
  }

 private:
  struct Variable {
    std::string label;
    uint64_t begin = 0, bytesPerRecord = 0, at = 0;
    bool record = false;
  };

  [[noreturn]] void fail(uint64_t at, const std::string& what) const {
    throwInput(path_, "", "",
               "corrupt netCDF header at byte " + std::to_string(at) + ": " + what,
               "check that the file is a complete Exodus II mesh");
  }

  void read(void* into, uint64_t n, const std::string& what) {
    if (n > size_ - pos_)
      fail(pos_, what + " needs " + std::to_string(n) + " bytes but only " +
                     std::to_string(size_ - pos_) + " remain (file truncated?)");
    in_.read(static_cast<char*>(into), static_cast<std::streamsize>(n));
    if (!in_) fail(pos_, "cannot read " + what);
    pos_ += n;
  }

  void skip(uint64_t n, const std::string& what) {
    if (n > size_ - pos_)
      fail(pos_, what + " declares " + std::to_string(n) + " bytes but only " +
                     std::to_string(size_ - pos_) + " remain (file truncated?)");
    in_.seekg(static_cast<std::streamoff>(pos_ + n));
    pos_ += n;
  }

  // A big-endian unsigned integer of `bytes` (4 or 8) bytes.
  uint64_t unsignedField(int bytes, const std::string& what = "a header field") {
    std::array<unsigned char, 8> b{};
    read(b.data(), static_cast<uint64_t>(bytes), what);
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | b[static_cast<std::size_t>(i)];
    return v;
  }

  // NON_NEG: a signed count that must be >= 0.
  uint64_t count(const std::string& what) {
    const uint64_t at = pos_;
    const uint64_t v = unsignedField(countBytes_, what);
    const uint64_t signBit = countBytes_ == 8 ? (uint64_t{1} << 63) : (uint64_t{1} << 31);
    if (v & signBit) fail(at, what + " is negative");
    return v;
  }

  std::string name(const std::string& what) {
    const uint64_t at = pos_;
    const uint64_t n = count("the length of the name of " + what);
    if (n == 0 || n > kMaxName)
      fail(at, "the name of " + what + " is " + std::to_string(n) +
                   " bytes long (netCDF names have 1 to 256)");
    std::string s(n, '\0');
    read(s.data(), n, "the name of " + what);
    skip(padded4(n) - n, "the padding of a name");
    return s;
  }

  // netCDF finds dimensions, variables and attributes by name: two of one name in a list make
  // exodus read one and size its buffer with the other.
  std::string uniqueName(const std::string& what, const std::string& kind,
                         std::set<std::string>& seen) {
    const uint64_t at = pos_;
    std::string nm = name(what);
    if (!seen.insert(nm).second) fail(at, "two " + kind + "s are named '" + nm + "'");
    return nm;
  }

  // The tag of a list and its number of elements; 0 elements for an absent list.
  uint64_t listHeader(uint32_t expectedTag, const std::string& what) {
    const uint64_t at = pos_;
    const uint64_t tag = unsignedField(4, "the tag of the " + what + " list");
    const uint64_t n = count("the number of " + what + "s");
    if (tag == kAbsent && n == 0) return 0;
    if (tag != expectedTag)
      fail(at, "the " + what + " list has tag " + std::to_string(tag) + " (expected " +
                   std::to_string(expectedTag) + ", or 0 for an empty list)");
    return n;
  }

  void readDimensions() {
    const uint64_t n = listHeader(kDimensionTag, "dimension");
    bool haveRecordDimension = false;
    for (uint64_t i = 0; i < n; ++i) {
      const std::string label = "dimension " + std::to_string(i);
      const std::string nm = uniqueName(label, "dimension", dimensionNames_);
      const uint64_t at = pos_;
      const uint64_t length = count("the length of dimension '" + nm + "'");
      if (length == 0) {
        if (haveRecordDimension) fail(at, "dimension '" + nm + "' is a second record dimension");
        haveRecordDimension = true;
      }
      dimensionLengths_.push_back(length);
    }
  }

  // The attributes of `owner` (a variable's label), or the global ones when it is empty.
  void readAttributes(const std::string& owner) {
    const bool global = owner.empty();
    const std::string what = global ? "a global attribute" : "an attribute of " + owner;
    const uint64_t n = listHeader(kAttributeTag, "attribute");
    std::set<std::string> names;
    for (uint64_t i = 0; i < n; ++i) {
      const std::string nm = uniqueName(what, "attribute", names);
      const uint64_t at = pos_;
      const uint32_t type = static_cast<uint32_t>(unsignedField(4, "an attribute type"));
      const uint64_t size = typeSize(type, version_);
      if (size == 0) fail(at, "attribute '" + nm + "' has unknown type " + std::to_string(type));
      const uint64_t values = count("the length of attribute '" + nm + "'");
      if (global && kScalarGlobalAttributes.count(nm) && values != 1)
        fail(at, "global attribute '" + nm + "' has " + std::to_string(values) +
                     " values (Exodus reads exactly one)");
      if (!global && kShortTextAttributes.count(nm) && values > kMaxShortText)
        fail(at, "attribute '" + nm + "' of " + owner + " has " +
                     std::to_string(values) + " characters (Exodus reads at most " +
                     std::to_string(kMaxShortText) + ")");
      const uint64_t bytes = productCapped(values, size, size_);
      skip(bytes > size_ ? bytes : padded4(bytes), "attribute '" + nm + "'");
    }
  }

  void readVariables() {
    const uint64_t n = listHeader(kVariableTag, "variable");
    for (uint64_t i = 0; i < n; ++i) {
      Variable v;
      const std::string nm =
          uniqueName("variable " + std::to_string(i), "variable", variableNames_);
      v.label = "variable '" + nm + "'";
      const uint64_t rank = count("the number of dimensions of " + v.label);
      uint64_t elements = 1;
      for (uint64_t k = 0; k < rank; ++k) {
        const uint64_t at = pos_;
        const uint64_t id = count("a dimension id of " + v.label);
        if (id >= dimensionLengths_.size())
          fail(at, v.label + " uses dimension id " + std::to_string(id) + " but the file has " +
                       std::to_string(dimensionLengths_.size()) + " dimensions");
        const uint64_t length = dimensionLengths_[id];
        if (length == 0) {
          if (k != 0) fail(at, v.label + " uses the record dimension after its first dimension");
          v.record = true;
        } else {
          elements = productCapped(elements, length, size_);
        }
      }
      readAttributes(v.label);
      const uint64_t at = pos_;
      const uint32_t type = static_cast<uint32_t>(unsignedField(4, "the type of " + v.label));
      const uint64_t size = typeSize(type, version_);
      if (size == 0) fail(at, v.label + " has unknown type " + std::to_string(type));
      v.bytesPerRecord = productCapped(elements, size, size_);
      unsignedField(countBytes_, "the size of " + v.label);  // vsize: redundant, may be clipped
      v.at = pos_;
      v.begin = unsignedField(offsetBytes_, "the data offset of " + v.label);
      variables_.push_back(v);
    }
  }

  // The data of a variable lies after the header and inside the file.
  void checkExtent(const Variable& v) const {
    if (v.begin < pos_)
      fail(v.at, v.label + " starts at byte " + std::to_string(v.begin) +
                     ", inside the header (which ends at byte " + std::to_string(pos_) + ")");
    // Up to the end of its last record (record variables) or of its data.
    const uint64_t bytes =
        !v.record ? v.bytesPerRecord
        : numrecs_ == 0
            ? 0
            : std::min(size_ + 1,
                       productCapped(recordBytes_, numrecs_ - 1, size_) + v.bytesPerRecord);
    std::string problem;
    if (v.begin > size_)
      problem = v.label + " starts at byte " + std::to_string(v.begin);
    else if (bytes > size_ - v.begin)
      problem = v.label + " needs " +
                (bytes > size_ ? "more than " + std::to_string(size_) : std::to_string(bytes)) +
                " bytes from byte " + std::to_string(v.begin);
    if (!problem.empty())
      throwInput(path_, "", "",
                 "data past the end of the file (truncated?): " + problem + " but the file has " +
                     std::to_string(size_) + " bytes",
                 "check that the file is a complete Exodus II mesh");
  }

  const std::string& path_;
  std::ifstream& in_;
  uint64_t size_;
  uint64_t pos_ = 0;
  uint64_t numrecs_ = 0;
  uint64_t recordBytes_ = 0;  // bytes of one record (all record variables)
  int version_ = 1, countBytes_ = 4, offsetBytes_ = 4;
  std::vector<uint64_t> dimensionLengths_;  // 0: the record dimension
  std::set<std::string> dimensionNames_, variableNames_;
  std::vector<Variable> variables_;
};

bool hasHdf5Signature(std::ifstream& in, uint64_t size) {
  static const char signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  for (uint64_t at = 0; at + 8 <= size; at = at == 0 ? 512 : 2 * at) {
    char b[8];
    in.clear();
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(b, 8)) return false;
    if (std::memcmp(b, signature, 8) == 0) return true;
  }
  return false;
}

}  // namespace

NetcdfStorage checkNetcdfHeader(const std::string& path) {
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) return NetcdfStorage::Unknown;
  char magic[4] = {0, 0, 0, 0};
  if (size >= 4 && in.read(magic, 4) && std::memcmp(magic, "CDF", 3) == 0 &&
      (magic[3] == 1 || magic[3] == 2 || magic[3] == 5)) {
    HeaderWalk(path, in, size).run(magic[3]);
    return NetcdfStorage::Classic;
  }
  return hasHdf5Signature(in, size) ? NetcdfStorage::Hdf5 : NetcdfStorage::Unknown;
}

}  // namespace choc
