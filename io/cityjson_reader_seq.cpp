// CityJSONSeq (.city.jsonl) back-end: line 1 is the CityJSON header, every further line one
// CityJSONFeature. A bad line is reported and skipped; the rest of the stream is still read.
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>

#include "io/cityjson_common.hpp"
#include "io/cityjson_reader_impl.hpp"

namespace mc::io {

namespace {

using nlohmann::json;

std::string short_reason(const json::exception& e) {
  std::string what = e.what();
  if (auto p = what.find("] "); p != std::string::npos && what[0] == '[') what = what.substr(p + 2);
  return what;
}

class SequenceReader : public CityJsonReader::Impl {
 public:
  explicit SequenceReader(const std::string& path) : source_(path == "-" ? "<stdin>" : path) {
    if (path == "-") {
      in_ = &std::cin;
    } else {
      file_.open(path, std::ios::binary);
      if (!file_) throw ReadError(path + ": cannot open: " + std::strerror(errno));
      in_ = &file_;
    }
    std::string line;
    if (!next_line(line))
      throw ReadError(source_ + ": empty file (a CityJSONSeq starts with a CityJSON header line)");
    json root;
    if (nested_deeper_than(line))
      throw ReadError(source_ + ": line " + std::to_string(line_no_) + ": JSON nested deeper than " +
                      std::to_string(kMaxJsonDepth) + " levels");
    try {
      root = json::parse(line);
    } catch (const json::exception& e) {
      throw ReadError(
          source_ + ": line " + std::to_string(line_no_) +
          ": not a CityJSONSeq header (a CityJSONSeq starts with one CityJSON object on one line): " +
          short_reason(e));
    }
    if (!root.is_object())
      throw ReadError(source_ + ": line " + std::to_string(line_no_) +
                      ": not a CityJSONSeq header (not a JSON object)");
    if (auto co = root.find("CityObjects"); co != root.end()) {
      if (co->is_object() && !co->empty())
        problems.push_back(source_ + ": the header line has " + std::to_string(co->size()) +
                           " CityObjects; CityJSONSeq keeps them in feature lines, so they are ignored");
      root.erase(co);
    }
    root.erase("vertices");
    header = make_header(std::move(root), source_);
    transform_ = parse_transform(header.root, source_);
  }

  bool sequence() const override { return true; }

  bool next(Feature& out) override {
    std::string line;
    while (next_line(line)) {
      if (read_feature(line, out)) return true;
    }
    return false;
  }

 private:
  bool next_line(std::string& line) {
    while (std::getline(*in_, line)) {
      ++line_no_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.find_first_not_of(" \t") != std::string::npos) return true;
    }
    return false;
  }

  bool skip(const std::string& why) {
    problems.push_back(source_ + ": line " + std::to_string(line_no_) + ": " + why + "; line skipped");
    return false;
  }

  bool read_feature(const std::string& line, Feature& out) {
    json doc;
    if (nested_deeper_than(line))
      return skip("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    try {
      doc = json::parse(line);
    } catch (const json::exception& e) { return skip("malformed JSON (" + short_reason(e) + ")"); }
    if (!doc.is_object()) return skip("not a JSON object");
    auto type = doc.find("type");
    if (type == doc.end() || *type != "CityJSONFeature")
      return skip("\"type\" is " + (type == doc.end() ? std::string("missing") : type->dump()) +
                  ", expected \"CityJSONFeature\"");
    auto objects = doc.find("CityObjects");
    if (objects == doc.end() || !objects->is_object() || objects->empty())
      return skip("\"CityObjects\" is missing, empty or not an object");

    out = Feature{};
    out.objects = std::move(*objects);
    auto id = doc.find("id");
    if (id != doc.end() && id->is_string() && out.objects.contains(id->get<std::string>())) {
      out.id = id->get<std::string>();
    } else {
      out.id = guess_root(out.objects);
      out.problems.push_back(out.id + ": feature line " + std::to_string(line_no_) +
                             " has no valid \"id\"; using this top-level object");
    }
    std::vector<mc::Vec3> verts = parse_vertices(doc, out);
    for (auto it = doc.begin(); it != doc.end(); ++it) {
      const std::string& k = it.key();
      if (k != "type" && k != "id" && k != "CityObjects" && k != "vertices")
        out.extra[k] = std::move(it.value());
    }
    localise_vertices(out, verts.size(), [&verts](const std::vector<uint64_t>& refs) {
      std::vector<mc::Vec3> v;
      v.reserve(refs.size());
      for (uint64_t r : refs) v.push_back(verts[r]);
      return v;
    });
    return true;
  }

  static std::string guess_root(const json& objects) {
    for (auto it = objects.begin(); it != objects.end(); ++it) {
      auto p = it->find("parents");
      if (!it->is_object() || p == it->end() || !p->is_array() || p->empty()) return it.key();
    }
    return objects.begin().key();
  }

  std::vector<mc::Vec3> parse_vertices(const json& doc, Feature& out) {
    std::vector<mc::Vec3> verts;
    auto v = doc.find("vertices");
    if (v == doc.end() || !v->is_array()) {
      out.problems.push_back(out.id + ": feature line " + std::to_string(line_no_) +
                             " has no \"vertices\" array; its geometry cannot be read");
      return verts;
    }
    ProblemLog log(out.problems, 20);
    verts.reserve(v->size());
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& e : *v) {
      if (e.is_array() && e.size() == 3 && e[0].is_number() && e[1].is_number() && e[2].is_number()) {
        verts.push_back(transform_.apply(e[0].get<double>(), e[1].get<double>(), e[2].get<double>()));
      } else {
        log.add(out.id + ": vertex #" + std::to_string(verts.size()) + " is not an array of 3 numbers");
        verts.emplace_back(nan, nan, nan);
      }
    }
    return verts;
  }

  std::string source_;
  std::ifstream file_;
  std::istream* in_ = nullptr;
  size_t line_no_ = 0;
  Transform transform_;
};

}  // namespace

std::unique_ptr<CityJsonReader::Impl> open_sequence_reader(const std::string& path) {
  return std::make_unique<SequenceReader>(path);
}

}  // namespace mc::io
