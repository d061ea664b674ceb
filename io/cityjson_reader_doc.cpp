// .city.json back-end. Pass 1 (cityjson_scan.cpp) indexes the file; pass 2 here, one feature per
// next(): reads the byte ranges of a top-level object and its descendants, parses each into a
// small DOM, and fetches only the vertices they reference from the spill file.
// Why byte ranges instead of a second SAX pass: next() is a pull interface, and random access
// lets a feature gather descendants that appear anywhere in the file (CityJSON does not order
// children after parents), while memory stays bounded by the largest feature.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "io/cityjson_common.hpp"
#include "io/cityjson_reader_impl.hpp"
#include "io/cityjson_scan.hpp"

namespace mc::io {

namespace {

class DocumentReader : public CityJsonReader::Impl {
 public:
  explicit DocumentReader(const std::string& path) : path_(path) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw ReadError(path + ": cannot open: " + std::strerror(errno));
    try {
      index_ = scan_document(fd_, path, spill_);
      header = make_header(std::move(index_.root), path);
      if (!index_.has_city_objects) throw ReadError(path + ": missing required member \"CityObjects\"");
      if (!index_.has_vertices) throw ReadError(path + ": missing required member \"vertices\"");
      transform_ = parse_transform(header.root, path);
      problems = std::move(index_.problems);
      resolve_hierarchy();
    } catch (...) {
      ::close(fd_);
      throw;
    }
  }
  ~DocumentReader() override { ::close(fd_); }

  bool sequence() const override { return false; }
  std::optional<size_t> feature_count() const override { return group_start_.size() - 1; }

  bool next(Feature& out) override {
    if (next_group_ >= group_start_.size() - 1) return false;
    const uint32_t g = next_group_++;
    out = Feature{};
    out.id = std::string(index_.id(index_.objects[members_[group_start_[g]]]));
    out.objects = nlohmann::json::object();
    std::string bytes;
    for (uint32_t k = group_start_[g]; k < group_start_[g + 1]; ++k) {
      const uint32_t i = members_[k];
      const ObjectEntry& e = index_.objects[i];
      const std::string id(index_.id(e));
      if (auto p = object_problems_.find(i); p != object_problems_.end())
        for (auto& msg : p->second) out.problems.push_back(std::move(msg));
      bytes.resize(e.end - e.begin);
      if (!read_at(e.begin, bytes.data(), bytes.size())) {
        out.problems.push_back(id + ": cannot re-read the object from the file; skipped");
        continue;
      }
      try {
        out.objects[id] = nlohmann::json::parse(bytes);
      } catch (const nlohmann::json::exception& ex) {  // only if the file changed between passes
        out.problems.push_back(id + ": cannot parse the object (" + std::string(ex.what()) + "); skipped");
      }
    }
    localise_vertices(out, index_.vertex_count,
                      [this](const std::vector<uint64_t>& refs) { return fetch(refs); });
    return true;
  }

 private:
  bool read_at(uint64_t offset, char* dst, size_t n) {
    size_t done = 0;
    while (done < n) {
      const ssize_t r = ::pread(fd_, dst + done, n - done, static_cast<off_t>(offset + done));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) return false;
      done += static_cast<size_t>(r);
    }
    return true;
  }

  // Reads the referenced raw vertices from the spill in runs (buildings use nearby indices).
  std::vector<mc::Vec3> fetch(const std::vector<uint64_t>& refs) {
    std::vector<mc::Vec3> out;
    out.reserve(refs.size());
    std::vector<double> buf;
    size_t a = 0;
    while (a < refs.size()) {
      size_t b = a;
      while (b + 1 < refs.size() && refs[b + 1] - refs[b] <= 32) ++b;
      const uint64_t first = refs[a], count = refs[b] - first + 1;
      buf.resize(count * 3);
      spill_.read_at(first * 3 * sizeof(double), buf.data(), buf.size() * sizeof(double));
      for (size_t k = a; k <= b; ++k) {
        const double* v = &buf[(refs[k] - first) * 3];
        out.push_back(transform_.apply(v[0], v[1], v[2]));
      }
      a = b + 1;
    }
    return out;
  }

  // Groups every object under one top-level owner: the first existing parent from "parents",
  // else an object listing it in "children"; cycles are broken and reported.
  void resolve_hierarchy() {
    const size_t n = index_.objects.size();
    std::unordered_map<std::string_view, uint32_t> by_id;
    by_id.reserve(n);
    std::vector<char> skip(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
      if (!by_id.emplace(index_.id(index_.objects[i]), i).second) {
        skip[i] = 1;
        problems.push_back("duplicate CityObject id \"" + std::string(index_.id(index_.objects[i])) +
                           "\"; the later copy is skipped");
      }
    }
    std::vector<int64_t> parent(n, -1);
    for (auto& [obj, name] : index_.parent_refs) {
      auto it = by_id.find(name);
      if (it == by_id.end())
        object_problems_[obj].push_back(std::string(index_.id(index_.objects[obj])) + ": parent \"" + name +
                                        "\" does not exist");
      else if (parent[obj] < 0 && it->second != obj) parent[obj] = it->second;
    }
    for (auto& [obj, name] : index_.child_refs) {
      auto it = by_id.find(name);
      if (it == by_id.end())
        object_problems_[obj].push_back(std::string(index_.id(index_.objects[obj])) + ": child \"" + name +
                                        "\" does not exist");
      else if (parent[it->second] < 0 && it->second != obj) parent[it->second] = obj;
    }
    index_.parent_refs.clear();
    index_.parent_refs.shrink_to_fit();
    index_.child_refs.clear();
    index_.child_refs.shrink_to_fit();

    std::vector<uint32_t> owner(n, 0);
    std::vector<char> state(n, 0);  // 0 unknown, 1 on the current path, 2 resolved
    std::vector<uint32_t> path;
    for (uint32_t i = 0; i < n; ++i) {
      if (state[i] || skip[i]) continue;
      path.clear();
      uint32_t j = i;
      while (state[j] == 0) {
        state[j] = 1;
        path.push_back(j);
        if (parent[j] < 0) break;
        j = static_cast<uint32_t>(parent[j]);
      }
      uint32_t root;
      if (state[j] == 2) {
        root = owner[j];
      } else if (parent[j] < 0) {
        root = j;
      } else {
        root = j;
        parent[j] = -1;
        object_problems_[j].push_back(std::string(index_.id(index_.objects[j])) +
                                      ": parents/children form a cycle; read as a top-level object");
      }
      for (uint32_t p : path) {
        owner[p] = root;
        state[p] = 2;
      }
    }
    // Counting sort by owner, roots in file order, each root first in its group.
    std::vector<uint32_t> group_of(n, UINT32_MAX);
    uint32_t groups = 0;
    for (uint32_t i = 0; i < n; ++i)
      if (!skip[i] && owner[i] == i) group_of[i] = groups++;
    group_start_.assign(groups + 1, 0);
    for (uint32_t i = 0; i < n; ++i)
      if (!skip[i]) ++group_start_[group_of[owner[i]] + 1];
    for (uint32_t g = 0; g < groups; ++g) group_start_[g + 1] += group_start_[g];
    members_.assign(group_start_[groups], 0);
    std::vector<uint32_t> fill(group_start_.begin(), group_start_.end() - 1);
    for (uint32_t i = 0; i < n; ++i)
      if (!skip[i] && owner[i] == i) members_[fill[group_of[i]]++] = i;
    for (uint32_t i = 0; i < n; ++i)
      if (!skip[i] && owner[i] != i) members_[fill[group_of[owner[i]]]++] = i;
  }

  std::string path_;
  int fd_ = -1;
  ScratchFile spill_;
  DocumentIndex index_;
  Transform transform_;
  std::vector<uint32_t> group_start_{0}, members_;
  std::unordered_map<uint32_t, std::vector<std::string>> object_problems_;
  uint32_t next_group_ = 0;
};

}  // namespace

std::unique_ptr<CityJsonReader::Impl> open_document_reader(const std::string& path) {
  return std::make_unique<DocumentReader>(path);
}

}  // namespace mc::io
