#include "mesh/MeshBytes.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace choc {

namespace {

constexpr uint64_t kMagic = 0x63686f636d657368;  // "chocmesh"

class Writer {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void text(const std::string& s) {
    value<uint64_t>(s.size());
    out += s;
  }
  template <class T>
  void array(const std::vector<T>& v) {
    value<uint64_t>(v.size());
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string out;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : in_(bytes) {}
  template <class T>
  T value() {
    T v;
    take(&v, sizeof v);
    return v;
  }
  std::string text() {
    std::string s(count(1), '\0');
    take(s.data(), s.size());
    return s;
  }
  template <class T>
  std::vector<T> array() {
    std::vector<T> v(count(sizeof(T)));
    take(v.data(), v.size() * sizeof(T));
    return v;
  }
  bool atEnd() const { return at_ == in_.size(); }

 private:
  // A count of items of `size` bytes that the remaining bytes can hold.
  std::size_t count(std::size_t size) {
    const uint64_t n = value<uint64_t>();
    if (n > (in_.size() - at_) / size) throw std::runtime_error("mesh bytes: truncated");
    return static_cast<std::size_t>(n);
  }
  void take(void* to, std::size_t n) {
    if (n > in_.size() - at_) throw std::runtime_error("mesh bytes: truncated");
    if (n > 0) std::memcpy(to, in_.data() + at_, n);
    at_ += n;
  }
  const std::string& in_;
  std::size_t at_ = 0;
};

}  // namespace

std::string meshToBytes(const Mesh& mesh) {
  Writer w;
  w.value(kMagic);
  w.text(mesh.title);
  w.value(mesh.dimension);
  w.array(mesh.coords);
  w.value<uint64_t>(mesh.blocks.size());
  for (const auto& b : mesh.blocks) {
    w.text(b.name);
    w.value(b.id);
    w.text(b.topology);
    w.value(b.nodesPerElement);
    w.array(b.connectivity);
  }
  w.value<uint64_t>(mesh.nodeSets.size());
  for (const auto& s : mesh.nodeSets) {
    w.text(s.name);
    w.value(s.id);
    w.array(s.nodes);
  }
  w.value<uint64_t>(mesh.sideSets.size());
  for (const auto& s : mesh.sideSets) {
    w.text(s.name);
    w.value(s.id);
    w.array(s.elements);
    w.array(s.sides);
  }
  return w.out;
}

Mesh meshFromBytes(const std::string& bytes) {
  Reader r(bytes);
  if (bytes.size() < sizeof kMagic || r.value<uint64_t>() != kMagic)
    throw std::runtime_error("mesh bytes: not written by meshToBytes");
  Mesh mesh;
  mesh.title = r.text();
  mesh.dimension = r.value<int>();
  mesh.coords = r.array<Point3>();
  // Each entity takes at least 8 bytes: a count beyond the bytes left is caught by the reads.
  for (auto n = r.value<uint64_t>(); n > 0; --n) {
    ElementBlock b;
    b.name = r.text();
    b.id = r.value<int>();
    b.topology = r.text();
    b.nodesPerElement = r.value<int>();
    b.connectivity = r.array<int>();
    mesh.blocks.push_back(std::move(b));
  }
  for (auto n = r.value<uint64_t>(); n > 0; --n) {
    NodeSet s;
    s.name = r.text();
    s.id = r.value<int>();
    s.nodes = r.array<int>();
    mesh.nodeSets.push_back(std::move(s));
  }
  for (auto n = r.value<uint64_t>(); n > 0; --n) {
    SideSet s;
    s.name = r.text();
    s.id = r.value<int>();
    s.elements = r.array<int>();
    s.sides = r.array<int>();
    mesh.sideSets.push_back(std::move(s));
  }
  if (!r.atEnd()) throw std::runtime_error("mesh bytes: trailing bytes");
  return mesh;
}

}  // namespace choc
