// CityGML read throughput and peak memory: reads every building of each file given (each in a
// child process, so that each peak RSS is the file's own) and prints buildings/s and peak RSS,
// then times the reader's first pass (citygml_prescan) alone: its share of the read.
// Without arguments: generates 5k- and 50k-building files with tools/gen_citygml.py in a
// temporary directory and compares them (peak RSS must not grow with the file).
//   build/tools/bench_citygml_read [FILE.gml ...] [--dump]   (--dump: print each feature's JSON)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io/citygml_prescan.hpp"
#include "io/citygml_reader.hpp"

namespace {

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

// Prints one line "file buildings parts vertices problems seconds buildings/s peakMB first-pass".
int read_file(const std::string& path, bool dump) {
  const auto t0 = std::chrono::steady_clock::now();
  size_t buildings = 0, objects = 0, vertices = 0, problems = 0;
  try {
    mc::io::CityGmlReader r(path);
    mc::io::Feature f;
    while (r.next(f)) {
      ++buildings;
      objects += f.objects.size();
      vertices += f.vertices.size();
      problems += f.problems.size();
      if (dump)
        std::printf("%s\n%s\n", f.objects.dump(1).c_str(), nlohmann::json(f.problems).dump(1).c_str());
    }
    if (dump)
      for (const auto& p : r.problems()) std::printf("file problem: %s\n", p.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double peak = peak_rss_mb();
  const auto t1 = std::chrono::steady_clock::now();
  mc::io::citygml::prescan(path);  // included in `s` already; timed again alone for its share
  const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  std::printf(
      "%-50s %8zu buildings %8zu objects %10zu vertices %6zu problems %7.2f s %9.0f buildings/s  peak RSS "
      "%6.1f MB  first pass %5.2f s (%2.0f%%)\n",
      std::filesystem::path(path).filename().c_str(), buildings, objects, vertices, problems, s,
      s > 0 ? static_cast<double>(buildings) / s : 0.0, peak, first, s > 0 ? 100.0 * first / s : 0.0);
  return 0;
}

int in_child(const std::string& path, bool dump) {
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    const int rc = read_file(path, dump);
    std::fflush(stdout);
    _exit(rc);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  bool dump = false;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--dump") dump = true;
    else files.push_back(argv[i]);
  }
  int rc = 0;
  if (files.empty()) {
    const auto dir = std::filesystem::temp_directory_path() / ("bench_citygml_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    // Beside this source file (CMake compiles it by absolute path).
    const std::string gen = (std::filesystem::path(__FILE__).parent_path() / "gen_citygml.py").string();
    for (int n : {5000, 50000}) {
      const std::string out = (dir / ("city_" + std::to_string(n) + ".gml")).string();
      const std::string cmd = "python3 " + gen + " " + std::to_string(n) + " " + out;
      if (std::system(cmd.c_str()) != 0) {
        std::fprintf(stderr, "failed: %s\n", cmd.c_str());
        rc = 1;
        break;
      }
      std::printf("%s: %.1f MB\n", out.c_str(), static_cast<double>(std::filesystem::file_size(out)) / 1e6);
      rc |= in_child(out, false);
    }
    std::filesystem::remove_all(dir);
    return rc;
  }
  for (const auto& f : files) rc |= in_child(f, dump);
  return rc;
}
