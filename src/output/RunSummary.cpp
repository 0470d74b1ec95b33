#include "output/RunSummary.hpp"

#include <cmath>
#include <cstdio>

namespace choc {

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::vector<std::string> split(const std::string& key) {
  std::vector<std::string> parts(1);
  for (char c : key) {
    if (c == '/') parts.emplace_back();
    else parts.back() += c;
  }
  return parts;
}

// A tree of the entries, for writing: leaves hold the index of their entry.
struct Node {
  std::string name;
  int entry = -1;
  std::vector<Node> children;
  Node& child(const std::string& n) {
    for (Node& c : children)
      if (c.name == n) return c;
    children.push_back({n, -1, {}});
    return children.back();
  }
};

}  // namespace

void RunSummary::put(const std::string& key, Value v) {
  for (auto& e : entries_)
    if (e.first == key) {
      e.second = std::move(v);
      return;
    }
  entries_.emplace_back(key, std::move(v));
}

void RunSummary::set(const std::string& key, double value) { put(key, value); }
void RunSummary::set(const std::string& key, long long value) { put(key, value); }
void RunSummary::set(const std::string& key, bool value) { put(key, value); }
void RunSummary::set(const std::string& key, const std::string& value) { put(key, value); }
void RunSummary::set(const std::string& key, const std::vector<double>& values) { put(key, values); }

bool RunSummary::has(const std::string& key) const {
  for (const auto& e : entries_)
    if (e.first == key) return true;
  return false;
}

namespace {

struct Writer {
  const std::vector<std::pair<std::string, std::variant<double, long long, bool, std::string, std::vector<double>>>>& entries;
  std::string out;

  void value(int entry) {
    const auto& v = entries[static_cast<std::size_t>(entry)].second;
    if (const auto* d = std::get_if<double>(&v)) out += number(*d);
    else if (const auto* i = std::get_if<long long>(&v)) out += std::to_string(*i);
    else if (const auto* b = std::get_if<bool>(&v)) out += *b ? "true" : "false";
    else if (const auto* s = std::get_if<std::string>(&v)) out += jsonString(*s);
    else {
      const auto& list = std::get<std::vector<double>>(v);
      out += "[";
      for (std::size_t k = 0; k < list.size(); ++k) out += (k ? ", " : "") + number(list[k]);
      out += "]";
    }
  }

  void object(const Node& n, const std::string& indent) {
    out += "{\n";
    for (std::size_t k = 0; k < n.children.size(); ++k) {
      const Node& c = n.children[k];
      out += indent + "  " + jsonString(c.name) + ": ";
      if (c.entry >= 0) value(c.entry);
      else object(c, indent + "  ");
      out += k + 1 < n.children.size() ? ",\n" : "\n";
    }
    out += indent + "}";
  }
};

}  // namespace

std::string RunSummary::json() const {
  Node root;
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    Node* n = &root;
    for (const std::string& part : split(entries_[k].first)) n = &n->child(part);
    n->entry = static_cast<int>(k);
  }
  Writer w{entries_, ""};
  w.object(root, "");
  return w.out + "\n";
}

}  // namespace choc
