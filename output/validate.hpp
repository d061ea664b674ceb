// `morphcut-city validate`: are a CityJSON file's objects well formed, is every BuildingPart we
// wrote a valid Solid (core/solid_validation.hpp), and do a building's parts tile its singleton
// cell at every level (no overlap, volumes add up to morphcut_cell_volume)? The file is read one
// feature at a time; memory is bounded by the largest feature.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/solid_validation.hpp"
#include "io/cityjson_types.hpp"

namespace mc::output {

// The Solid rules default to val3dity's default tolerances and its own vertex merge test
// (core/solid_validation.hpp, val3dity_exact_tolerances), and overlaps to its exact test, so that
// a report says what val3dity says about the file (docs/output-format.md §Validity).
struct ValidateOptions {
  double planarity =
      val3dity_exact_tolerances().planarity;  // m: face points off the face's least-squares plane
  double normals_deg =
      val3dity_exact_tolerances().normals_deg;  // degrees between a face's triangles' normals
  // m³: common volume two parts of one level may have and still only touch; 0 = val3dity's exact
  // test (any common interior is an overlap).
  double overlap = 0;
  double snap = val3dity_exact_tolerances().snap;  // m: vertices closer than this are one vertex
  double volume_rel = 1e-6;  // relative tolerance of volume sums (the quantisation bound is added)
};

// Codes beyond val3dity's (which core/solid_validation.hpp uses for the Solids).
namespace validate_code {
constexpr int kPartsOverlap = 601;          // val3dity's BUILDINGPARTS_OVERLAP
constexpr int kPartsVolumeMismatch = 701;   // a level's parts do not add up to the cell volume
constexpr int kLevelsVolumeMismatch = 702;  // two levels of one building differ in volume
constexpr int kPartCountMismatch = 703;     // morphcut_parts / morphcut_levels vs the parts present
constexpr int kOverlapNotComputed = 704;    // the exact common volume could not be computed
constexpr int kPartsStatusMismatch = 705;   // parts of a failed/skipped building, or none for ok
constexpr int kReadProblem = 910;           // the reader's complaint about this object
constexpr int kParentsChildren = 912;       // "parents"/"children" do not mirror each other
constexpr int kInvalidObject = 913;         // required members missing or of the wrong kind
}  // namespace validate_code
const char* validate_error_name(int code);

struct ValidationError {
  int code = 0;
  std::string name, message;
};

struct ObjectReport {
  std::string id, type;
  std::vector<ValidationError> errors;
  std::string note;  // e.g. "no parts (status skipped)"
  // Our BuildingParts only:
  std::optional<double> level, volume, convexity;
  bool valid() const { return errors.empty(); }
};

struct ValidationCounts {
  size_t features = 0, objects = 0;
  size_t buildings = 0, buildings_with_parts = 0, buildings_without_parts = 0, invalid_buildings = 0;
  size_t parts = 0, valid_parts = 0, invalid_parts = 0;
  size_t other_invalid_objects = 0;  // input objects with structure errors
  size_t overlap_tests = 0;          // part pairs whose overlap needed exact constructions
  // Largest |sum of a level's part volumes - cell volume| / cell volume seen (how tight the
  // volume check really is, next to its tolerance).
  double max_volume_deviation = 0;
};

struct ValidationSummary {
  std::string file;
  ValidationCounts counts;
  std::vector<std::string> file_problems;  // reader problems of the file as a whole
  bool valid() const {
    return file_problems.empty() && counts.invalid_parts == 0 && counts.invalid_buildings == 0 &&
           counts.other_invalid_objects == 0;
  }
};

// Every object of one feature (the building first, then its parts in "children" order, then
// any other object with errors); counts updated.
std::vector<ObjectReport> validate_feature(const mc::io::Feature& f, const mc::io::Header& h,
                                           const ValidateOptions& opt, ValidationCounts& counts);

// The whole file; `sink` receives every report in file order. Throws io::ReadError when the file
// cannot be read as CityJSON at all.
ValidationSummary validate_city(const std::string& path, const ValidateOptions& opt = {},
                                const std::function<void(const ObjectReport&)>& sink = {});

}  // namespace mc::output
