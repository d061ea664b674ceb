// morphcut-city reproject IN -o OUT --to CRS: a whole city in another CRS (io/reproject.hpp), e.g.
// a geographic output in a metric CRS for validators whose tolerances are metres (val3dity).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "io/cityjson_writer.hpp"
#include "io/errors.hpp"
#include "io/feature_source.hpp"
#include "io/reproject.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommands.hpp"

namespace mc::cli {

int reproject_main(int argc, char** argv) {
  CLI::App app{"morphcut-city reproject - write a city (CityJSON, CityJSONSeq or CityGML) in another CRS",
               "morphcut-city reproject"};
  std::string input, output, to, from;
  double scale = 0;
  app.add_option("INPUT", input, "input city (any format morphcut-city reads)")->required();
  app.add_option("-o,--output", output, "output CityJSON (.jsonl: CityJSONSeq)")->required();
  app.add_option("--to", to, "target CRS, e.g. EPSG:32631 or EPSG:4979")->required();
  app.add_option("--from", from, "the input's CRS, when the file does not say it (or says it wrongly)");
  app.add_option(
         "--scale", scale,
         "horizontal grid of the output transform (default 1e-8 for degrees, 0.001 for metres); heights "
         "keep the input's")
      ->check(CLI::PositiveNumber);
  app.footer(
      "Horizontal coordinates are transformed with PROJ (offline: no grid is fetched); heights are kept "
      "as they are. Geographic coordinates are written longitude first.\n"
      "Exit codes: 0 written, 2 usage, read, CRS or write error (nothing written).");
  if (const auto code = parse_or_exit(app, argc, argv)) return *code;
  try {
    mc::io::ReprojectedSource src(mc::io::open_feature_source(input), to,
                                  scale > 0 ? std::optional<double>(scale) : std::nullopt, from);
    mc::io::CityJsonWriter writer(output, src.header());
    mc::io::Feature f;
    size_t n = 0;
    while (src.next(f)) {
      writer.write(f);
      ++n;
    }
    writer.close();
    std::fprintf(stderr, "morphcut-city reproject: %zu features -> %s (%s)\n", n, output.c_str(), to.c_str());
    return 0;
  } catch (const std::exception& e) { std::fprintf(stderr, "morphcut-city reproject: %s\n", e.what()); }
  return kExitUsage;
}

}  // namespace mc::cli
