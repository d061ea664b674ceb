// CityJSON I/O throughput on the 3D BAG tile (MB/s), and the streaming reader's memory claim:
// peak RSS of reading the tile vs the tile replicated 10x must stay nearly flat (target <= 1.5x).
//
//   bench_cityjson_io [--no_rss_check] [google-benchmark flags]
//   MC_BENCH_TILE=<file.city.json> overrides the tile.
#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "io/cityjson.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using namespace mc::io;

std::string tile_path(const char* ext = ".city.json") {
  if (const char* t = std::getenv("MC_BENCH_TILE"); t && *t && std::string(ext) == ".city.json") return t;
  return (fs::path(__FILE__).parent_path().parent_path() / "datasets/3dbag" /
          ("3dbag_5910" + std::string(ext)))
      .string();
}

std::string scratch_dir() {
  const char* t = std::getenv("TMPDIR");
  fs::path d = fs::path(t && *t ? t : "/tmp") / ("mc_bench_io_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d.string();
}

std::vector<Feature> read_features(const std::string& path, Header* header = nullptr) {
  CityJsonReader r(path);
  if (header) *header = r.header();
  std::vector<Feature> out;
  Feature f;
  while (r.next(f)) out.push_back(std::move(f));
  return out;
}

// ---- throughput ----

void BM_Read(benchmark::State& state, const char* ext) {
  const std::string path = tile_path(ext);
  size_t n = 0;
  for (auto _ : state) {
    CityJsonReader r(path);
    Feature f;
    while (r.next(f)) ++n;
    benchmark::DoNotOptimize(n);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * fs::file_size(path)));
}
BENCHMARK_CAPTURE(BM_Read, city_json, ".city.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Read, city_jsonl, ".city.jsonl")->Unit(benchmark::kMillisecond);

void BM_ReadExtract(benchmark::State& state) {
  const std::string path = tile_path();
  size_t faces = 0;
  for (auto _ : state) {
    CityJsonReader r(path);
    Feature f;
    while (r.next(f))
      if (is_building(f)) faces += extract_building(f, r.header()).mesh.faces.size();
    benchmark::DoNotOptimize(faces);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * fs::file_size(path)));
}
BENCHMARK(BM_ReadExtract)->Unit(benchmark::kMillisecond);

void BM_Write(benchmark::State& state) {
  Header h;
  const auto features = read_features(tile_path(), &h);
  const std::string out = scratch_dir() + "/write.city.json";
  for (auto _ : state) {
    CityJsonWriter w(out, h);
    for (const auto& f : features) w.write(f);
    w.close();
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * fs::file_size(out)));
  fs::remove_all(fs::path(out).parent_path());
}
BENCHMARK(BM_Write)->Unit(benchmark::kMillisecond);

void BM_ReadWrite(benchmark::State& state) {
  const std::string in = tile_path(), out = scratch_dir() + "/rw.city.json";
  for (auto _ : state) {
    CityJsonReader r(in);
    CityJsonWriter w(out, r.header());
    Feature f;
    while (r.next(f)) w.write(f);
    w.close();
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * fs::file_size(in)));
  fs::remove_all(fs::path(out).parent_path());
}
BENCHMARK(BM_ReadWrite)->Unit(benchmark::kMillisecond);

// ---- peak RSS, measured in fresh child processes ----

// The tile n times, ids (and parent/child links) suffixed with "-r<k>", streamed by our writer.
int make_replica(const std::string& in, const std::string& out, int n) {
  Header h;
  const auto features = read_features(in, &h);
  CityJsonWriter w(out, h);
  auto rename = [](const std::string& id, int k) { return id + "-r" + std::to_string(k); };
  for (int k = 0; k < n; ++k) {
    for (const auto& f : features) {
      Feature c;
      c.id = rename(f.id, k);
      c.vertices = f.vertices;
      c.objects = nlohmann::json::object();
      for (auto it = f.objects.begin(); it != f.objects.end(); ++it) {
        nlohmann::json o = *it;
        for (const char* link : {"parents", "children"})
          if (o.contains(link))
            for (auto& id : o[link]) id = rename(id.get<std::string>(), k);
        c.objects[rename(it.key(), k)] = std::move(o);
      }
      w.write(c);
    }
  }
  w.close();
  return 0;
}

long vm_hwm_kb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  return -1;
}

// What the pipeline does with a file: read every feature and extract every building.
int rss_child(const std::string& path) {
  size_t buildings = 0;
  if (path != "none") {
    CityJsonReader r(path);
    Feature f;
    while (r.next(f))
      if (is_building(f) && !extract_building(f, r.header()).mesh.empty()) ++buildings;
  }
  std::printf("%ld %zu\n", vm_hwm_kb(), buildings);
  return 0;
}

struct ChildResult {
  long maxrss_kb = -1, hwm_kb = -1;
  size_t buildings = 0;
};

// posix_spawn + wait4: ru_maxrss of the child; the child also reports its own VmHWM.
ChildResult run_child(const std::vector<std::string>& args) {
  int pipefd[2];
  if (::pipe(pipefd) != 0) return {};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, pipefd[1], 1);
  posix_spawn_file_actions_addclose(&fa, pipefd[0]);
  std::vector<char*> argv;
  std::string self = fs::read_symlink("/proc/self/exe").string();
  argv.push_back(self.data());
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  const int rc = posix_spawn(&pid, self.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(pipefd[1]);
  ChildResult res;
  if (rc != 0) {
    ::close(pipefd[0]);
    return res;
  }
  std::string text;
  char buf[256];
  ssize_t n;
  while ((n = ::read(pipefd[0], buf, sizeof buf)) > 0) text.append(buf, static_cast<size_t>(n));
  ::close(pipefd[0]);
  int status = 0;
  struct rusage ru {};
  ::wait4(pid, &status, 0, &ru);
  res.maxrss_kb = ru.ru_maxrss;
  std::sscanf(text.c_str(), "%ld %zu", &res.hwm_kb, &res.buildings);
  return res;
}

void rss_check() {
  const std::string dir = scratch_dir(), tile = tile_path(), replica = dir + "/tile_x10.city.json";
  run_child({"--make-replica", tile, replica, "10"});
  if (!fs::exists(replica)) {
    std::fprintf(stderr, "rss check: could not generate %s\n", replica.c_str());
    return;
  }
  const auto base = run_child({"--rss-child", "none"});
  const auto one = run_child({"--rss-child", tile});
  const auto ten = run_child({"--rss-child", replica});
  auto mb = [](long kb) { return kb / 1024.0; };
  std::printf("peak RSS (read + extract every building), ru_maxrss via wait4 / VmHWM:\n");
  std::printf("  process baseline        : %7.1f MB / %7.1f MB\n", mb(base.maxrss_kb), mb(base.hwm_kb));
  std::printf("  1x tile  (%6.1f MB, %5zu buildings): %7.1f MB / %7.1f MB\n", fs::file_size(tile) / 1048576.0,
              one.buildings, mb(one.maxrss_kb), mb(one.hwm_kb));
  std::printf("  10x tile (%6.1f MB, %5zu buildings): %7.1f MB / %7.1f MB\n",
              fs::file_size(replica) / 1048576.0, ten.buildings, mb(ten.maxrss_kb), mb(ten.hwm_kb));
  const double ratio = static_cast<double>(ten.maxrss_kb) / static_cast<double>(one.maxrss_kb);
  std::printf("  ratio 10x / 1x          : %.2f (target <= 1.5) %s\n\n", ratio,
              ratio <= 1.5 ? "OK" : "OVER TARGET");
  std::fflush(stdout);
  fs::remove_all(dir);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[1]) == "--rss-child") return rss_child(argv[2]);
  if (argc >= 5 && std::string(argv[1]) == "--make-replica")
    return make_replica(argv[2], argv[3], std::atoi(argv[4]));
  bool check = true;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) == "--no_rss_check") check = false;
    else rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  // First, while this process is still small: a spawned child's ru_maxrss starts from ours.
  if (check) rss_check();
  benchmark::Initialize(&n, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
