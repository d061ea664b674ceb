// AtomicFile: complete-or-absent outputs, temp cleanup on destruction and on signals.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "io/atomic_file.hpp"

namespace fs = std::filesystem;
using mc::io::AtomicFile;

namespace {

// Death-test children (threadsafe style: a fresh exec of this binary) re-run SetUp; they must
// land in their parent's directory, so the parent can check what the child left behind.
int owner_pid() { return GTEST_FLAG_GET(internal_run_death_test).empty() ? ::getpid() : ::getppid(); }

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mc_atomic_" + std::to_string(owner_pid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // Temp files left in dir_.
  std::vector<std::string> temps() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename().string().find(".tmp.") != std::string::npos) out.push_back(e.path().string());
    return out;
  }
  fs::path dir_;
};

TEST_F(AtomicFileTest, CommitReplacesTheTarget) {
  const fs::path target = dir_ / "report.json";
  std::ofstream(target) << "old";
  {
    AtomicFile f(target.string());
    EXPECT_EQ(f.temp_path(), fs::absolute(target).string() + ".tmp." + std::to_string(::getpid()));
    EXPECT_TRUE(fs::exists(f.temp_path()));
    EXPECT_TRUE(f.signal_protected());
    f.stream() << "new contents\n";
    EXPECT_EQ(slurp(target), "old");  // readers see the old file until commit
    f.commit();
    EXPECT_TRUE(f.committed());
    EXPECT_THROW(f.commit(), std::logic_error);
  }
  EXPECT_EQ(slurp(target), "new contents\n");
  EXPECT_TRUE(temps().empty());
  EXPECT_EQ(mc::io::registered_temp_files(), 0);
}

TEST_F(AtomicFileTest, NoCommitLeavesTargetAndRemovesTemp) {
  const fs::path target = dir_ / "out.csv";
  std::ofstream(target) << "previous";
  {
    AtomicFile f(target.string());
    f.stream() << "partial";
    EXPECT_EQ(mc::io::registered_temp_files(), 1);
  }
  EXPECT_EQ(slurp(target), "previous");
  EXPECT_TRUE(temps().empty());
  EXPECT_EQ(mc::io::registered_temp_files(), 0);
}

TEST_F(AtomicFileTest, ExceptionWhileWritingLeavesNothing) {
  const fs::path target = dir_ / "new.json";
  try {
    AtomicFile f(target.string());
    f.stream() << "half";
    throw std::runtime_error("job failed");
  } catch (const std::runtime_error&) {}
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(temps().empty());
}

TEST_F(AtomicFileTest, SamePathTwiceInOneProcessIsRejected) {
  const fs::path target = dir_ / "x";
  AtomicFile a(target.string());
  EXPECT_THROW(AtomicFile b(target.string()), std::logic_error);
  a.commit();
  AtomicFile c(target.string());  // the name is free again
}

TEST_F(AtomicFileTest, UnwritableDirectoryThrows) {
  EXPECT_THROW(AtomicFile((dir_ / "missing" / "f").string()), std::system_error);
  EXPECT_EQ(mc::io::registered_temp_files(), 0);
}

TEST_F(AtomicFileTest, ManyThreadsDistinctFiles) {
  std::vector<std::thread> ts;
  for (int t = 0; t < 8; ++t)
    ts.emplace_back([&, t] {
      for (int i = 0; i < 50; ++i) {
        AtomicFile f((dir_ / ("f" + std::to_string(t) + "_" + std::to_string(i))).string());
        f.stream() << t << ' ' << i;
        if (i % 2 == 0) f.commit();
      }
    });
  for (auto& t : ts) t.join();
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) (void)e, ++files;
  EXPECT_EQ(files, 8 * 25);
  EXPECT_EQ(mc::io::registered_temp_files(), 0);
}

// The child dies by SIGTERM while writing; its temp file must be gone, the target untouched.
TEST_F(AtomicFileTest, SigtermUnlinksTempFiles) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path target = dir_ / "tile.city.json";
  std::ofstream(target) << "previous run";
  EXPECT_EXIT(
      {
        mc::io::install_temp_cleanup_signal_handlers();
        AtomicFile a(target.string());
        AtomicFile b((dir_ / "tile.csv").string());
        a.stream() << "partial" << std::flush;
        if (!fs::exists(a.temp_path()) || !fs::exists(b.temp_path())) std::_Exit(3);
        ::raise(SIGTERM);
        std::_Exit(4);  // not reached: the default action terminates
      },
      ::testing::KilledBySignal(SIGTERM), "");
  EXPECT_TRUE(temps().empty());
  EXPECT_EQ(slurp(target), "previous run");
  EXPECT_FALSE(fs::exists(dir_ / "tile.csv"));
}

// A handler installed before ours still runs (after the cleanup).
int g_chained = 0;
void chained_handler(int) { g_chained = 1; }

TEST_F(AtomicFileTest, SigintChainsToThePreviousHandler) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path target = dir_ / "a.json";
  EXPECT_EXIT(
      {
        ::signal(SIGINT, chained_handler);
        mc::io::install_temp_cleanup_signal_handlers();
        AtomicFile a(target.string());
        ::raise(SIGINT);
        std::_Exit(g_chained == 1 && !fs::exists(a.temp_path()) ? 7 : 8);
      },
      ::testing::ExitedWithCode(7), "");
  EXPECT_TRUE(temps().empty());
}

}  // namespace
