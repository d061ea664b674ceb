// What the command-line front ends (morphcut-city and its subcommands) share.
#pragma once
#include <optional>

#include <CLI/CLI.hpp>

namespace mc::cli {

// Usage, configuration, read or write error: nothing was written.
constexpr int kExitUsage = 2;

// Parses argv; when that ends the program (--help, --version, or a usage error, which CLI11
// prints) returns the exit code: 0 for help/version, kExitUsage otherwise.
inline std::optional<int> parse_or_exit(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) { return app.exit(e) == 0 ? 0 : kExitUsage; }
  return std::nullopt;
}

}  // namespace mc::cli
