// Subcommands of morphcut-city other than the decomposition run itself:
//   morphcut-city validate FILE ...        (tools/cli/validate_cli.cpp)
//   morphcut-city merge-reports ...        (tools/cli/merge_reports_cli.cpp)
//   morphcut-city html REPORT [CITY ...]   (tools/cli/html_report_cli.cpp)
//   morphcut-city reproject IN -o OUT --to CRS  (tools/cli/reproject_cli.cpp)
// Each takes argv with argv[0] = the subcommand name and returns the process exit code.
#pragma once

namespace mc::cli {

int validate_main(int argc, char** argv);
int merge_reports_main(int argc, char** argv);
int html_main(int argc, char** argv);
int reproject_main(int argc, char** argv);

}  // namespace mc::cli
