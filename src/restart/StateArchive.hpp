// The state a transient needs to continue, as named records (a checkpoint's content): each
// part of a run (time stepper, contact, links, energy integrals, output files) writes its own
// records under its own prefix and reads them back on restart. Records are raw doubles,
// integers, bytes or text; distributed vectors are stored in global DOF order (see
// StateVectors.hpp), so a checkpoint does not depend on the number of ranks that wrote it.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace choc {

// A missing or malformed record (the checkpoint belongs to another kind of run or version).
struct StateRecordError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class StateArchive {
 public:
  void putBytes(const std::string& name, std::vector<char> bytes);
  void putText(const std::string& name, const std::string& text);
  void putDouble(const std::string& name, double v) { putVector(name, std::vector<double>{v}); }
  void putInt(const std::string& name, long long v) { putVector(name, std::vector<long long>{v}); }
  template <class T>
  void putVector(const std::string& name, const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable<T>::value, "raw records only");
    const char* p = reinterpret_cast<const char*>(v.data());
    putBytes(name, std::vector<char>(p, p + v.size() * sizeof(T)));
  }
  // A trivially copyable struct (link states, responses), stored as its bytes.
  template <class T>
  void putPod(const std::string& name, const T& x) {
    putVector(name, std::vector<T>{x});
  }

  bool has(const std::string& name) const { return records_.count(name) > 0; }
  const std::vector<char>& bytes(const std::string& name) const;
  std::string text(const std::string& name) const;
  double getDouble(const std::string& name) const { return single<double>(name); }
  long long getInt(const std::string& name) const { return single<long long>(name); }
  template <class T>
  std::vector<T> getVector(const std::string& name) const {
    static_assert(std::is_trivially_copyable<T>::value, "raw records only");
    const std::vector<char>& b = bytes(name);
    if (b.size() % sizeof(T) != 0)
      throw StateRecordError("record '" + name + "' has " + std::to_string(b.size()) +
                             " bytes, not a whole number of values");
    std::vector<T> v(b.size() / sizeof(T));
    if (!v.empty()) std::copy(b.begin(), b.end(), reinterpret_cast<char*>(v.data()));
    return v;
  }
  template <class T>
  T getPod(const std::string& name) const { return single<T>(name); }
  // Throws StateRecordError unless the record holds exactly n values of T.
  template <class T>
  std::vector<T> getVector(const std::string& name, std::size_t n) const {
    std::vector<T> v = getVector<T>(name);
    if (v.size() != n)
      throw StateRecordError("record '" + name + "' has " + std::to_string(v.size()) +
                             " values, " + std::to_string(n) + " expected");
    return v;
  }

  // Serialised form: "<count>" then per record "<name length><name><byte count><bytes>"
  // (64-bit little-endian lengths). parse() throws StateRecordError on a malformed buffer.
  std::vector<char> serialize() const;
  static StateArchive parse(const std::vector<char>& buffer);
  std::size_t size() const { return records_.size(); }

 private:
  template <class T>
  T single(const std::string& name) const {
    return getVector<T>(name, 1)[0];
  }
  std::map<std::string, std::vector<char>> records_;
};

// FNV-1a, 64 bits: the checksum of checkpoint files and the hashes of inputs and meshes.
std::uint64_t fnv1a(const void* data, std::size_t n, std::uint64_t h = 1469598103934665603ULL);
std::string hex64(std::uint64_t h);

}  // namespace choc
