#include "pipeline/run_input.hpp"

#include <cstdio>
#include <vector>

#include "io/errors.hpp"
#include "io/reproject.hpp"
#include "io/sha256.hpp"
#include "pipeline/interrupt.hpp"
#include "pipeline/run.hpp"

namespace mc::pipeline {

namespace {

// The file's SHA-256 on its own thread (the only other reader of the file). It gives up on an
// interrupt, so that stopping never waits for a gigabyte to be hashed.
std::future<std::string> hash_async(const std::string& path) {
  return std::async(std::launch::async, [path] {
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) return std::string();
    mc::io::Sha256 sha;
    std::vector<char> buf(1 << 20);
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), f.get())) > 0) {
      if (interrupt_signal()) return std::string();
      sha.update(buf.data(), n);
    }
    return std::ferror(f.get()) ? std::string() : sha.hex();
  });
}

// Features in a CityJSONSeq file = non-empty lines after the first; for the progress bar only.
std::optional<size_t> count_sequence_features(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return std::nullopt;
  size_t lines = 0;
  bool content = false;
  std::vector<char> buf(1 << 20);
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), f.get())) > 0)
    for (size_t i = 0; i < n; ++i) {
      if (buf[i] == '\n') {
        lines += content;
        content = false;
      } else if (buf[i] != ' ' && buf[i] != '\r' && buf[i] != '\t') {
        content = true;
      }
    }
  lines += content;
  return lines > 0 ? std::optional<size_t>(lines - 1) : std::nullopt;
}

}  // namespace

RunInput open_run_input(const RunOptions& opt) {
  RunInput in;
  if (opt.input != "-") in.sha256 = hash_async(opt.input);
  in.source = mc::io::open_feature_source(opt.input);
  if (!opt.output_crs.empty()) {
    try {
      in.source = std::make_unique<mc::io::ReprojectedSource>(std::move(in.source), opt.output_crs);
    } catch (const mc::io::ReadError&) { throw; } catch (const std::exception& e) {
      throw mc::io::ReadError("--output-crs " + opt.output_crs + ": " + e.what());
    }
  }
  in.header = in.source->header();
  in.grid = mc::output::refine_output_grid(in.header);
  return in;
}

std::optional<size_t> feature_total(const RunOptions& opt, const mc::io::FeatureSource& source) {
  std::optional<size_t> total = source.feature_count();
  if (!total && opt.progress && opt.input != "-" && opt.input.ends_with(".jsonl"))
    total = count_sequence_features(opt.input);
  return total;
}

}  // namespace mc::pipeline
