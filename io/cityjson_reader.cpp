#include "io/cityjson_reader.hpp"

#include <algorithm>
#include <set>

#include "io/cityjson_common.hpp"
#include "io/crs.hpp"
#include "io/cityjson_reader_impl.hpp"

namespace mc::io {

namespace {}  // namespace

CityJsonReader::CityJsonReader(const std::string& path)
    : impl_(path == "-" || path.ends_with(".jsonl") ? open_sequence_reader(path)
                                                    : open_document_reader(path)) {}
CityJsonReader::~CityJsonReader() = default;
CityJsonReader::CityJsonReader(CityJsonReader&&) noexcept = default;
CityJsonReader& CityJsonReader::operator=(CityJsonReader&&) noexcept = default;

const Header& CityJsonReader::header() const { return impl_->header; }
bool CityJsonReader::next(Feature& out) { return impl_->next(out); }
const std::vector<std::string>& CityJsonReader::problems() const { return impl_->problems; }
bool CityJsonReader::is_sequence() const { return impl_->sequence(); }
std::optional<size_t> CityJsonReader::feature_count() const { return impl_->feature_count(); }

Header make_header(nlohmann::json root, const std::string& source) {
  auto type = root.find("type");
  if (type == root.end() || !type->is_string() || type->get<std::string>() != "CityJSON")
    throw ReadError(source + ": not a CityJSON file (\"type\" is " +
                    (type == root.end() ? std::string("missing") : type->dump()) +
                    ", expected \"CityJSON\")");
  check_version(root, source);
  parse_transform(root, source);  // validate once here; users re-parse the cheap object
  Header h;
  h.version = root["version"].get<std::string>();
  h.crs = parse_crs(root);
  h.coords = coordinate_system(h.crs, /*axis_order_of_crs=*/false, &h.coords_note);
  h.root = std::move(root);
  return h;
}

void localise_vertices(Feature& out, uint64_t source_count, const VertexFetch& fetch) {
  ProblemLog log(out.problems);
  std::vector<uint64_t> refs;
  for_each_vertex_ref(
      out.objects, [&](nlohmann::json& leaf, const std::string& id, const std::string& where) {
        if (leaf.is_number_unsigned() || (leaf.is_number_integer() && leaf.get<int64_t>() >= 0)) {
          const auto i = leaf.get<uint64_t>();
          if (i < source_count) {
            refs.push_back(i);
            return;
          }
          log.add(id + ": " + where + ": vertex index " + std::to_string(i) + " out of range (" +
                  std::to_string(source_count) + " vertices)");
        } else {
          std::string text = leaf.dump();
          if (text.size() > 40) text = text.substr(0, 40) + "...";
          log.add(id + ": " + where + ": " + text + " is not a vertex index");
        }
        leaf = -1;
      });
  std::sort(refs.begin(), refs.end());
  refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
  out.vertices = fetch(refs);
  std::set<std::string> reported;
  for_each_vertex_ref(out.objects, [&](nlohmann::json& leaf, const std::string& id,
                                       const std::string& where) {
    if (!leaf.is_number_integer() || leaf.get<int64_t>() < 0) return;  // already reported
    const auto local =
        static_cast<size_t>(std::lower_bound(refs.begin(), refs.end(), leaf.get<uint64_t>()) - refs.begin());
    leaf = local;
    if (!mc::is_finite(out.vertices[local]) && reported.insert(id + where).second)
      log.add(id + ": " + where + ": uses a vertex with non-finite coordinates (NaN or inf)");
  });
}

}  // namespace mc::io
