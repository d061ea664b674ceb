// morphcut-city validate FILE: argument handling only (the checks are output/validate.hpp).
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommands.hpp"
#include "output/validate.hpp"
#include "output/validate_report.hpp"

namespace mc::cli {

using namespace mc::output;

namespace {

const char* kValidateFooter = R"(Checks:
  every CityObject: required members, "parents"/"children" mirrored, the reader's problems
  every morphcut BuildingPart (attribute morphcut_level), val3dity 2.6's codes and rules at its
    default tolerances (vertices merged as val3dity merges them, the shell built from the faces'
    triangles as val3dity builds it): 101 TOO_FEW_POINTS, 102 CONSECUTIVE_POINTS_SAME,
    104 RING_SELF_INTERSECTION, 105 RING_COLLAPSED, 201 INTERSECTION_RINGS,
    203 NON_PLANAR_POLYGON_DISTANCE_PLANE, 204 NON_PLANAR_POLYGON_NORMALS_DEVIATION,
    205 POLYGON_INTERIOR_DISCONNECTED, 206 INNER_RING_OUTSIDE, 207 INNER_RINGS_NESTED,
    208 ORIENTATION_RINGS_SAME, 300 NOT_VALID_2_MANIFOLD, 301 TOO_FEW_POLYGONS, 302 SHELL_NOT_CLOSED,
    303 NON_MANIFOLD_CASE, 305 MULTIPLE_CONNECTED_COMPONENTS, 306 SHELL_SELF_INTERSECTION,
    307 POLYGON_WRONG_ORIENTATION, 405 WRONG_ORIENTATION_SHELL
  every building with parts: 601 BUILDINGPARTS_OVERLAP (an input Solid left at the parts' LoD,
    parts of several levels at one LoD, or two parts of a level whose interiors meet: exact, as
    val3dity tests it, or a common volume above --tolerance-overlap), 701 PARTS_VOLUME_MISMATCH
    (sum of part volumes vs morphcut_cell_volume, relative 1e-6 plus the file's quantisation
    bound), 702 LEVELS_VOLUME_MISMATCH, 703 PART_COUNT_MISMATCH (morphcut_parts),
    704 OVERLAP_NOT_COMPUTED, 705 PARTS_STATUS_MISMATCH
  structure: 910 READ_PROBLEM, 912 PARENTS_CHILDREN_INCONSISTENT, 913 INVALID_CITYOBJECT
Buildings with status failed or skipped have no parts: reported as a note, not an error.

Exit codes:
  0  every object valid
  1  some objects invalid (listed on stdout, or in the JSON report)
  2  usage error, unreadable file, or a file-level structure problem
)";

}  // namespace

int validate_main(int argc, char** argv) {
  CLI::App app{"morphcut-city validate - check a CityJSON file and every morphcut part in it",
               "morphcut-city validate"};
  std::string file, json_out;
  ValidateOptions opt;
  bool quiet = false;
  app.add_option("FILE", file, ".city.json or .city.jsonl (CityJSONSeq)")->required();
  app.add_option("--json", json_out, "write the JSON report to this file (- = stdout)");
  app.add_option("--tolerance-planarity", opt.planarity,
                 "max distance of a face's points to its plane, m (default 0.01, val3dity's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--tolerance-normals", opt.normals_deg,
                 "max angle between the normals of a face's triangles, degrees (default 20, val3dity's; 0 = "
                 "not checked)")
      ->check(CLI::NonNegativeNumber);
  app.add_option(
         "--tolerance-overlap", opt.overlap,
         "common volume two parts may have and still only touch, m³ (default 0: val3dity's exact test, any "
         "common interior overlaps)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--quiet,-q", quiet, "print nothing; only the exit code (and --json) tell");
  app.footer(kValidateFooter);
  if (const auto code = parse_or_exit(app, argc, argv)) return *code;

  try {
    std::unique_ptr<mc::io::AtomicFile> json_file;
    std::ostream* json_stream = nullptr;
    if (json_out == "-") {
      json_stream = &std::cout;
    } else if (!json_out.empty()) {
      json_file = std::make_unique<mc::io::AtomicFile>(json_out);
      json_stream = &json_file->stream();
    }
    // Text goes to stdout unless the JSON does.
    std::ostream* text = quiet ? nullptr : (json_out == "-" ? &std::cerr : &std::cout);
    std::optional<JsonValidationWriter> writer;
    if (json_stream) writer.emplace(*json_stream, file, opt);
    const ValidationSummary s = validate_city(file, opt, [&](const ObjectReport& r) {
      if (writer) writer->object(r);
      if (text && !r.valid()) write_text_errors(*text, r);
    });
    if (writer) writer->finish(s);
    if (json_file) json_file->commit();
    if (text) write_text_summary(*text, s);
    if (!s.file_problems.empty()) return kExitUsage;
    return s.valid() ? 0 : 1;
  } catch (const mc::io::ReadError& e) {
    std::fprintf(stderr, "morphcut-city validate: cannot read %s: %s\n", file.c_str(), e.what());
  } catch (const std::exception& e) { std::fprintf(stderr, "morphcut-city validate: error: %s\n", e.what()); }
  return kExitUsage;
}

}  // namespace mc::cli
