// .city.json output is streamed: CityObjects go straight to the output file while their vertices
// are spooled (as text) to a scratch file beside it, appended as "vertices" on close(). Memory
// therefore holds one feature at a time, whatever the size of the city.
#include "io/cityjson_writer.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/cityjson_common.hpp"
#include "io/scratch_file.hpp"

namespace mc::io {

using nlohmann::json;

struct CityJsonWriter::Impl {
  Impl(const std::string& path, const Header& header)
      : file(path), sequence(path.size() >= 6 && path.compare(path.size() - 6, 6, ".jsonl") == 0) {
    try {
      transform = parse_transform(header.root, path);
    } catch (const std::exception& e) { throw WriteError(e.what()); }
    json root = header.root;
    root.erase("CityObjects");
    root.erase("vertices");
    root.erase("type");
    root.erase("version");
    std::ostream& o = file.stream();
    o << "{\"type\":\"CityJSON\",\"version\":" << json(header.version).dump();
    for (auto it = root.begin(); it != root.end(); ++it)
      o << ',' << json(it.key()).dump() << ':' << it->dump();
    if (sequence) {
      o << ",\"CityObjects\":{},\"vertices\":[]}\n";
    } else {
      spool = std::make_unique<ScratchFile>(std::filesystem::path(path).parent_path().string().empty()
                                                ? std::string(".")
                                                : std::filesystem::path(path).parent_path().string());
      o << ",\"CityObjects\":{";
    }
  }

  // One vertex as JSON text: integers when a transform is present (null for non-finite input,
  // which keeps the defect visible instead of inventing a coordinate).
  void vertex_text(const mc::Vec3& v, std::string& s) const {
    s += '[';
    const double c[3] = {v.x, v.y, v.z};
    const double t[3] = {transform.translate.x, transform.translate.y, transform.translate.z};
    const double k[3] = {transform.scale.x, transform.scale.y, transform.scale.z};
    for (int i = 0; i < 3; ++i) {
      if (i) s += ',';
      if (!std::isfinite(c[i])) {
        s += "null";
      } else if (transform.present) {
        char buf[32];
        const long long q = std::llround((c[i] - t[i]) / k[i]);
        auto r = std::to_chars(buf, buf + sizeof buf, q);
        s.append(buf, r.ptr);
      } else {
        s += json(c[i]).dump();
      }
    }
    s += ']';
  }

  void write(const Feature& f) {
    if (closed) throw std::logic_error("CityJsonWriter::write after close()");
    std::ostream& o = file.stream();
    std::string verts;
    for (size_t i = 0; i < f.vertices.size(); ++i) {
      if (i || (!sequence && vertex_offset)) verts += ',';
      vertex_text(f.vertices[i], verts);
    }
    if (sequence) {
      o << "{\"type\":\"CityJSONFeature\",\"id\":" << json(f.id).dump()
        << ",\"CityObjects\":" << f.objects.dump() << ",\"vertices\":[" << verts << ']';
      if (f.extra.is_object())
        for (auto it = f.extra.begin(); it != f.extra.end(); ++it)
          o << ',' << json(it.key()).dump() << ':' << it->dump();
      o << "}\n";
    } else {
      json objects = f.objects;
      const auto offset = static_cast<int64_t>(vertex_offset);
      for_each_vertex_ref(objects, [offset](json& leaf, const std::string&, const std::string&) {
        if (leaf.is_number_integer() && leaf.get<int64_t>() >= 0) leaf = leaf.get<int64_t>() + offset;
      });
      for (auto it = objects.begin(); it != objects.end(); ++it) {
        if (objects_written++) o << ',';
        o << json(it.key()).dump() << ':' << it->dump();
      }
      spool->append(verts);
      vertex_offset += f.vertices.size();
      if (f.extra.is_object() && !f.extra.empty()) ++dropped;
    }
    if (!o) throw WriteError(file.path() + ": write failed");
    ++features;
  }

  void close() {
    if (closed) return;
    closed = true;
    std::ostream& o = file.stream();
    if (!sequence) {
      o << "},\"vertices\":[";
      std::vector<char> buf(1 << 20);
      for (uint64_t at = 0; at < spool->size(); at += buf.size()) {
        const size_t n = static_cast<size_t>(std::min<uint64_t>(buf.size(), spool->size() - at));
        spool->read_at(at, buf.data(), n);
        o.write(buf.data(), static_cast<std::streamsize>(n));
      }
      o << "]}\n";
    }
    file.commit();
  }

  AtomicFile file;
  bool sequence;
  Transform transform;
  std::unique_ptr<ScratchFile> spool;
  uint64_t vertex_offset = 0;
  size_t objects_written = 0, features = 0, dropped = 0;
  bool closed = false;
};

// AtomicFile reports std::system_error; callers of this module get WriteError with the reason.
CityJsonWriter::CityJsonWriter(const std::string& path, const Header& header) {
  try {
    impl_ = std::make_unique<Impl>(path, header);
  } catch (const std::system_error& e) { throw WriteError(path + ": " + e.what()); }
}
CityJsonWriter::~CityJsonWriter() = default;
void CityJsonWriter::write(const Feature& f) { impl_->write(f); }
void CityJsonWriter::close() {
  try {
    impl_->close();
  } catch (const std::system_error& e) { throw WriteError(impl_->file.path() + ": " + e.what()); }
}
size_t CityJsonWriter::features_written() const { return impl_->features; }
size_t CityJsonWriter::dropped_extras() const { return impl_->dropped; }

}  // namespace mc::io
