// The per-building cache (pipeline/cache.hpp) on real tiles: a warm run does no geometry work and
// writes byte-identical outputs; changed buildings, other configs and damaged entries miss.
#include <algorithm>
#include <fstream>

#include "io/cityjson.hpp"
#include "pipeline/cache.hpp"
#include "pipeline/run.hpp"
#include "pipeline_fixtures.hpp"

namespace mc::pipeline {
using namespace mc::massing;
using namespace mc::output;
using namespace mc::report;
namespace {

using mc::test::json;
using mc::test::slurp;
namespace fs = std::filesystem;

struct CachedRun {
  RunResult result;
  std::string output, report, summary;
};

CachedRun run_with(const std::string& input, const std::string& dir, const std::string& tag,
                   const std::string& cache, Params p = mc::test::default_config().params) {
  const bool seq = input.size() > 6 && input.substr(input.size() - 6) == ".jsonl";
  CachedRun r;
  r.output = dir + "/" + tag + (seq ? ".city.jsonl" : ".city.json");
  r.report = dir + "/" + tag + ".report.json";
  r.summary = dir + "/" + tag + ".csv";
  RunOptions opt;
  opt.input = input;
  opt.output = r.output;
  opt.report = r.report;
  opt.summary = r.summary;
  opt.cache_dir = cache;
  r.result = run_city(opt, p, mc::test::default_config().run);
  return r;
}

std::vector<std::string> entries(const std::string& cache) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(cache))
    if (e.is_regular_file()) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The delft subset (10 buildings, CityJSONSeq) without cache, with a cold cache and warm, once
// for the whole suite: the geometry work is the expensive part.
class CacheTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    input_ = mc::test::data_file("3dbag/delft_subset.city.jsonl");
    if (input_.empty()) return;
    dir_ = new mc::test::TempDir("cache");
    cache_ = *dir_ / "cache";
    plain_ = run_with(input_, dir_->path.string(), "plain", "");
    cold_ = run_with(input_, dir_->path.string(), "cold", cache_);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  void SetUp() override {
    if (input_.empty()) GTEST_SKIP() << "test data 3dbag/delft_subset.city.jsonl not found";
  }
  static inline std::string input_, cache_;
  static inline mc::test::TempDir* dir_ = nullptr;
  static inline CachedRun plain_, cold_;
};

TEST_F(CacheTest, ColdRunStoresEveryCompleteBuildingAndChangesNothing) {
  EXPECT_EQ(cold_.result.buildings, 10u);
  EXPECT_EQ(cold_.result.cache.hits, 0u);
  EXPECT_EQ(cold_.result.cache.misses, 10u);
  const size_t complete = cold_.result.counts.at("ok") + cold_.result.counts.at("skipped");
  EXPECT_EQ(cold_.result.cache.stored, complete);
  EXPECT_EQ(cold_.result.cache.not_stored, 10u - complete);
  EXPECT_EQ(entries(cache_).size(), complete);
  EXPECT_EQ(slurp(cold_.output), slurp(plain_.output));
  EXPECT_EQ(slurp(cold_.summary), slurp(plain_.summary));
  const json report = json::parse(slurp(cold_.report));
  EXPECT_EQ(report["cache"]["misses"], 10);
  EXPECT_TRUE(json::parse(slurp(plain_.report))["cache"].is_null());
}

TEST_F(CacheTest, WarmRunHitsEverythingWithIdenticalBytesAndNoGeometryWork) {
  const CachedRun warm = run_with(input_, dir_->path.string(), "warm", cache_);
  EXPECT_EQ(warm.result.cache.hits, cold_.result.cache.stored);
  EXPECT_EQ(warm.result.cache.misses, cold_.result.cache.not_stored);
  EXPECT_EQ(slurp(warm.output), slurp(plain_.output));
  EXPECT_EQ(slurp(warm.summary), slurp(plain_.summary));
  // The report's per-building timings show that no preprocessing or decomposition ran.
  const json report = json::parse(slurp(warm.report));
  EXPECT_EQ(report["cache"]["hits"], warm.result.cache.hits);
  for (const auto& b : report["buildings"])
    if (b["status"] == "ok") {
      EXPECT_EQ(b["timings"]["preprocess"], 0) << b["id"];
      EXPECT_EQ(b["timings"]["decompose"], 0) << b["id"];
      EXPECT_GT(b["levels"].size(), 0u);
    }
}

TEST_F(CacheTest, RerunOnItsOwnOutputHitsTheSameEntries) {
  // Earlier parts are stripped before the key is taken, as the job itself does.
  const CachedRun again = run_with(cold_.output, dir_->path.string(), "again", cache_);
  EXPECT_EQ(again.result.cache.hits, cold_.result.cache.stored);
  const CachedRun plain_again = run_with(cold_.output, dir_->path.string(), "plain_again", "");
  EXPECT_EQ(slurp(again.output), slurp(plain_again.output));
}

TEST_F(CacheTest, AChangedBuildingMissesAndTheOthersHit) {
  // The first feature moved 1 m east (1000 units of its 1 mm transform).
  std::istringstream in(slurp(input_));
  std::string line, text;
  for (int i = 0; std::getline(in, line); ++i) {
    if (i == 1) {
      json f = json::parse(line);
      for (auto& v : f["vertices"]) v[0] = v[0].get<int64_t>() + 1000;
      line = f.dump();
    }
    text += line + "\n";
  }
  const std::string changed = *dir_ / "changed.city.jsonl";
  write(changed, text);
  const std::string cache =
      *dir_ / "cache_changed";  // a copy: the suite's cache stays as the cold run left it
  fs::copy(cache_, cache, fs::copy_options::recursive);
  const CachedRun mixed = run_with(changed, dir_->path.string(), "mixed", cache);
  EXPECT_EQ(mixed.result.cache.misses, 1u + cold_.result.cache.not_stored);
  EXPECT_EQ(mixed.result.cache.hits, cold_.result.cache.stored - 1);
  const CachedRun reference = run_with(changed, dir_->path.string(), "changed_plain", "");
  EXPECT_EQ(slurp(mixed.output), slurp(reference.output));
  EXPECT_EQ(slurp(mixed.summary), slurp(reference.summary));
}

TEST_F(CacheTest, DamagedEntriesAreRecomputedNeverTrusted) {
  mc::test::TempDir dir("cache_damaged");
  const std::string cache = dir / "cache";
  fs::copy(cache_, cache, fs::copy_options::recursive);
  auto files = entries(cache);
  ASSERT_GE(files.size(), 4u);
  // One flipped byte in the payload, one truncated entry, and one valid entry of another
  // building put under this building's name.
  std::string a = slurp(files[0]);
  a[a.size() - 10] ^= 0x01;
  write(files[0], a);
  const std::string b = slurp(files[1]);
  write(files[1], b.substr(0, b.size() / 2));
  write(files[2], slurp(files[3]));
  const CachedRun r = run_with(input_, dir.path.string(), "damaged", cache);
  EXPECT_EQ(r.result.cache.corrupt, 3u);
  EXPECT_EQ(r.result.cache.hits, cold_.result.cache.stored - 3);
  EXPECT_EQ(slurp(r.output), slurp(plain_.output));
  // The recomputed results were stored again.
  const CachedRun next = run_with(input_, dir.path.string(), "next", cache);
  EXPECT_EQ(next.result.cache.corrupt, 0u);
  EXPECT_EQ(next.result.cache.hits, cold_.result.cache.stored);
}

TEST_F(CacheTest, AnotherConfigMissesButThreadCountDoesNot) {
  MC_REQUIRE_DATA(small, "3dbag/3dbag_b2.city.json");
  mc::test::TempDir dir("cache_config");
  const std::string cache = dir / "cache";
  Params p = mc::test::default_config().params;
  p.threads = 2;
  const CachedRun first = run_with(small, dir.path.string(), "first", cache, p);
  ASSERT_GT(first.result.cache.stored, 0u);
  p.threads = 1;
  const CachedRun one_thread = run_with(small, dir.path.string(), "one", cache, p);
  EXPECT_EQ(one_thread.result.cache.hits, first.result.cache.stored);
  EXPECT_EQ(slurp(one_thread.output), slurp(first.output));
  Params other = p;
  other.dec.sigma *= 2;
  const CachedRun sigma = run_with(small, dir.path.string(), "sigma", cache, other);
  EXPECT_EQ(sigma.result.cache.hits, 0u);
  EXPECT_EQ(sigma.result.cache.misses, first.result.buildings);
}

TEST(CacheKey, FollowsGeometryNotVertexNumberingOrAttributes) {
  MC_REQUIRE_DATA(small, "3dbag/3dbag_b2.city.json");
  mc::io::CityJsonReader reader(small);
  mc::io::Feature f;
  ASSERT_TRUE(reader.next(f));
  mc::test::TempDir dir("cache_key");
  const mc::LoadedConfig cfg = mc::test::default_config();
  BuildingCache cache(dir / "c", reader.header(), cfg.params, cfg.run);
  const std::string key = cache.key_of(f);
  EXPECT_EQ(key.size(), 64u);
  EXPECT_EQ(cache.entry_path(key), (dir.path / "c" / key.substr(0, 2) / (key + ".json")).string());

  mc::io::Feature renumbered = f;  // an unused vertex first: every index shifts, no coordinate does
  renumbered.vertices.insert(renumbered.vertices.begin(), Vec3{1, 2, 3});
  mc::io::for_each_vertex_ref(renumbered.objects, [](json& leaf, const std::string&, const std::string&) {
    leaf = leaf.get<int64_t>() + 1;
  });
  EXPECT_EQ(cache.key_of(renumbered), key);

  mc::io::Feature attributed = f;
  attributed.objects[f.id]["attributes"]["note"] = "changed";
  EXPECT_EQ(cache.key_of(attributed), key);

  mc::io::Feature moved = f;
  moved.vertices[0].z += 0.001;  // one grid step
  EXPECT_NE(cache.key_of(moved), key);

  mc::io::Feature relabelled = f;
  bool changed = false;
  for (auto& [id, obj] : relabelled.objects.items())
    for (auto& g : obj["geometry"])
      if (g.contains("semantics") && !changed) {
        g["semantics"]["surfaces"][0]["type"] = "ClosureSurface";
        changed = true;
      }
  ASSERT_TRUE(changed);
  EXPECT_NE(cache.key_of(relabelled), key);
}

}  // namespace
}  // namespace mc::pipeline
