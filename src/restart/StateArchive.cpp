#include "restart/StateArchive.hpp"

#include <cstdio>
#include <cstring>

namespace choc {

void StateArchive::putBytes(const std::string& name, std::vector<char> bytes) {
  records_[name] = std::move(bytes);
}

void StateArchive::putText(const std::string& name, const std::string& text) {
  putBytes(name, std::vector<char>(text.begin(), text.end()));
}

const std::vector<char>& StateArchive::bytes(const std::string& name) const {
  const auto it = records_.find(name);
  if (it == records_.end()) throw StateRecordError("record '" + name + "' is missing");
  return it->second;
}

std::string StateArchive::text(const std::string& name) const {
  const std::vector<char>& b = bytes(name);
  return std::string(b.begin(), b.end());
}

namespace {

void putLength(std::vector<char>& out, std::uint64_t n) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((n >> (8 * i)) & 0xff));
}

std::uint64_t getLength(const std::vector<char>& in, std::size_t& pos) {
  if (in.size() - pos < 8) throw StateRecordError("archive truncated");
  std::uint64_t n = 0;
  for (int i = 0; i < 8; ++i) n |= std::uint64_t(static_cast<unsigned char>(in[pos + i])) << (8 * i);
  pos += 8;
  return n;
}

}  // namespace

std::vector<char> StateArchive::serialize() const {
  std::vector<char> out;
  putLength(out, records_.size());
  for (const auto& [name, b] : records_) {
    putLength(out, name.size());
    out.insert(out.end(), name.begin(), name.end());
    putLength(out, b.size());
    out.insert(out.end(), b.begin(), b.end());
  }
  return out;
}

StateArchive StateArchive::parse(const std::vector<char>& in) {
  StateArchive a;
  std::size_t pos = 0;
  const std::uint64_t count = getLength(in, pos);
  for (std::uint64_t r = 0; r < count; ++r) {
    const std::uint64_t nameLength = getLength(in, pos);
    if (nameLength == 0 || nameLength > 4096 || in.size() - pos < nameLength)
      throw StateRecordError("archive: bad record name length");
    std::string name(in.begin() + pos, in.begin() + pos + nameLength);
    pos += nameLength;
    const std::uint64_t n = getLength(in, pos);
    if (in.size() - pos < n) throw StateRecordError("archive: record '" + name + "' truncated");
    a.records_[name] = std::vector<char>(in.begin() + pos, in.begin() + pos + n);
    pos += n;
  }
  if (pos != in.size()) throw StateRecordError("archive: trailing bytes");
  return a;
}

std::uint64_t fnv1a(const void* data, std::size_t n, std::uint64_t h) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

std::string hex64(std::uint64_t h) {
  char b[20];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

}  // namespace choc
