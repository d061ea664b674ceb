// Internal: the two reader back-ends and the shared feature assembly.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "io/cityjson_reader.hpp"

namespace mc::io {

struct CityJsonReader::Impl {
  virtual ~Impl() = default;
  virtual bool next(Feature& out) = 0;
  virtual bool sequence() const = 0;
  virtual std::optional<size_t> feature_count() const { return std::nullopt; }
  Header header;
  std::vector<std::string> problems;
};

std::unique_ptr<CityJsonReader::Impl> open_document_reader(const std::string& path);
std::unique_ptr<CityJsonReader::Impl> open_sequence_reader(const std::string& path);

// Fills the header from a root JSON (type, version, transform, CRS checks); throws ReadError.
Header make_header(nlohmann::json root, const std::string& source);

// Validates every vertex reference of `out.objects` against `source_count` source vertices,
// renumbers them densely (in source order) and fetches the coordinates of the referenced ones.
// Bad references become -1 with a problem naming the object. `fetch` gets the sorted distinct
// source indices and returns their real-world coordinates.
using VertexFetch = std::function<std::vector<mc::Vec3>(const std::vector<uint64_t>&)>;
void localise_vertices(Feature& out, uint64_t source_count, const VertexFetch& fetch);

}  // namespace mc::io
