// Hostile XML: entity declarations ("billion laughs"), a 2 GB text node in a 2 MB gzip file, a
// million levels of nesting, truncated gzip. Each is refused with a clear ReadError in under a
// second and under 100 MB, measured in a child process (a hang or a crash is a failure too, not a
// stuck test run). The files are generated here, into a scratch directory.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>

#include "tests/io/citygml_test_util.hpp"

namespace mc::io::test {
namespace {

struct Outcome {
  bool finished = false;  // the child reported back in time
  std::string message;    // the ReadError's, "no error", or another exception's
  double seconds = -1, grown_mb = -1;
};

double resident_mb() {
  long pages = 0, resident = 0;
  std::ifstream("/proc/self/statm") >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Opens and reads the whole file in a forked child: wall time and peak RSS growth of the read.
Outcome read_in_child(const std::string& path, int timeout_s = 30) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    // A child starts with its parent's peak RSS: reset it (Linux), then measure from here.
    { std::ofstream("/proc/self/clear_refs") << "5"; }
    const double base = resident_mb();
    const auto t0 = std::chrono::steady_clock::now();
    std::string message = "no error";
    try {
      CityGmlReader r(path);
      Feature f;
      while (r.next(f)) {}
    } catch (const ReadError& e) { message = e.what(); } catch (const std::exception& e) {
      message = std::string("not a ReadError: ") + e.what();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const double numbers[2] = {seconds, static_cast<double>(u.ru_maxrss) / 1024.0 - base};
    message.resize(std::min<size_t>(message.size(), 4000));
    const bool ok = write(fds[1], numbers, sizeof numbers) == sizeof numbers &&
                    write(fds[1], message.data(), message.size()) == static_cast<ssize_t>(message.size());
    _exit(ok ? 0 : 1);
  }
  close(fds[1]);
  Outcome out;
  std::string bytes;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{fds[0], POLLIN, 0};
    if (left.count() <= 0 || poll(&p, 1, static_cast<int>(left.count())) <= 0) {
      kill(pid, SIGKILL);  // hung: the test fails on `finished`
      break;
    }
    char buf[4096];
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    bytes.append(buf, static_cast<size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && bytes.size() >= 2 * sizeof(double)) {
    double numbers[2];
    std::memcpy(numbers, bytes.data(), sizeof numbers);
    out = {true, bytes.substr(sizeof numbers), numbers[0], numbers[1]};
  }
  return out;
}

// The refusal: this message, in under a second, in under 100 MB.
void expect_refused(const std::string& path, const std::string& message) {
  const Outcome o = read_in_child(path);
  ASSERT_TRUE(o.finished) << path << ": the read hung or crashed";
  EXPECT_NE(o.message.find(message), std::string::npos) << o.message;
  EXPECT_EQ(o.message.rfind(path + ": ", 0), 0u) << o.message;  // names the file
  EXPECT_LT(o.seconds, 1.0) << o.message;
  EXPECT_LT(o.grown_mb, 100.0) << o.message;
  std::cout << "refused in " << o.seconds << " s, peak RSS +" << o.grown_mb << " MB: " << o.message << "\n";
}

// One gzip member of `data` (members concatenate into one stream: gzip -d reads them all).
std::string gzip_member(const std::string& data) {
  z_stream z{};
  deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&z, data.size()) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  return out;
}

const char* kRoot =
    R"(<CityModel xmlns="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
 xmlns:gml="http://www.opengis.net/gml">)";

std::string billion_laughs() {
  std::string s = "<?xml version=\"1.0\"?>\n<!DOCTYPE CityModel [\n <!ENTITY lol \"lol\">\n";
  for (int i = 1; i <= 9; ++i) {
    s += " <!ENTITY lol" + std::to_string(i) + " \"";
    for (int j = 0; j < 10; ++j) s += "&lol" + (i > 1 ? std::to_string(i - 1) : std::string()) + ";";
    s += "\">\n";
  }
  return s + "]>\n" + kRoot + "<cityObjectMember><bldg:Building><gml:name>&lol9;</gml:name></bldg:Building>" +
         "</cityObjectMember></CityModel>\n";
}

TEST(CityGmlHostile, EntityDeclarationsAreRefusedFastAndSmall) {
  ScratchDir dir;
  const std::string laughs = billion_laughs();
  ASSERT_LT(laughs.size(), 1500u);  // 1 KB that would expand to 3 GB
  const std::string plain = dir.file("laughs.gml");
  std::ofstream(plain) << laughs;
  expect_refused(plain, "entity declarations are not accepted in CityGML (<!ENTITY in the DOCTYPE, line 3)");

  // The same in UTF-16 (with a byte order mark): the check reads code units.
  std::string utf16 = "\xFF\xFE";
  std::string decl = laughs;
  decl.replace(decl.find("?>"), 2, " encoding=\"UTF-16\"?>");
  for (char c : decl) utf16 += std::string{c, '\0'};
  const std::string wide = dir.file("laughs16.gml");
  std::ofstream(wide, std::ios::binary) << utf16;
  expect_refused(wide, "entity declarations are not accepted in CityGML");

  // Gzip, and a parameter entity hidden behind a comment and a quoted '>'.
  const std::string gz = dir.file("laughs.gml.gz");
  std::ofstream(gz, std::ios::binary) << gzip_member(laughs);
  expect_refused(gz, "entity declarations are not accepted in CityGML");
  const std::string param = dir.file("param.gml");
  std::ofstream(param) << "<?xml version=\"1.0\"?>\n<!DOCTYPE CityModel SYSTEM \"x>.dtd\" [ <!-- ]> --> "
                          "<!ENTITY % p \"<!ENTITY a 'b'>\"> %p; ]>\n"
                       << kRoot << "</CityModel>\n";
  expect_refused(param, "entity declarations are not accepted in CityGML");
}

TEST(CityGmlHostile, ADoctypeWithoutEntitiesIsReadAndNothingIsFetched) {
  ScratchDir dir;
  const std::string path = dir.file("doctype.gml");
  // "<!ENTITY" inside a comment and a quoted "]>" are not declarations; the external DTD is never
  // loaded (no network, no file).
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<!-- <!ENTITY not a declaration> -->\n"
                         "<!DOCTYPE CityModel SYSTEM \"http://example.invalid/citygml.dtd\" [\n"
                         " <!-- a comment with <!ENTITY in it -->\n <!ELEMENT CityModel ANY>\n"
                         " <!ATTLIST CityModel note CDATA \"]>\">\n]>\n"
                      << kRoot
                      << "<cityObjectMember><bldg:Building gml:id=\"a\"/></cityObjectMember></CityModel>\n";
  const auto r = read_gml(path);
  ASSERT_EQ(r.features.size(), 1u);
  EXPECT_EQ(r.features[0].id, "a");
}

TEST(CityGmlHostile, ATwoGigabyteTextNodeInATwoMegabyteGzipFailsFastAndSmall) {
  ScratchDir dir;
  const std::string path = dir.file("huge_text.gml.gz");
  {
    std::ofstream out(path, std::ios::binary);
    out << gzip_member(std::string(kRoot) +
                       "<cityObjectMember><bldg:Building><bldg:lod2MultiSurface><gml:MultiSurface>"
                       "<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>");
    std::string chunk;
    while (chunk.size() + 6 <= (1u << 20)) chunk += "0 0 0 ";
    const std::string member = gzip_member(chunk);
    for (int i = 0; i < 2048; ++i) out << member;  // 2048 x 1 MB of one text node
    out << gzip_member(
        "</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>"
        "</gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building></cityObjectMember></CityModel>");
  }
  const auto size = fs::file_size(path);
  EXPECT_LT(size, 4u << 20) << size;
  expect_refused(path, "a text node is longer than 10,000,000 bytes, libxml2's limit");
}

TEST(CityGmlHostile, AMillionNestingLevelsFailFastAndSmall) {
  ScratchDir dir;
  const std::string path = dir.file("deep.gml");
  {
    std::ofstream out(path);
    out << kRoot << "<cityObjectMember><bldg:Building>";
    for (int i = 0; i < 1000000; ++i) out << "<a>";
    for (int i = 0; i < 1000000; ++i) out << "</a>";
    out << "</bldg:Building></cityObjectMember></CityModel>";
  }
  expect_refused(path, "elements are nested deeper than 256 levels, libxml2's limit");
}

TEST(CityGmlHostile, TruncatedGzipFailsClearly) {
  ScratchDir dir;
  std::string xml = std::string(kRoot);
  for (int i = 0; i < 300; ++i)
    xml +=
        "<cityObjectMember><bldg:Building gml:id=\"b" + std::to_string(i) +
        "\"><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon><gml:exterior>"
        "<gml:LinearRing><gml:posList>" +
        std::to_string(i) + " 0 0 1 0 0 1 1 0 " + std::to_string(i) +
        " 0 "
        "0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface>"
        "</bldg:lod2MultiSurface></bldg:Building></cityObjectMember>";
  xml += "</CityModel>\n";
  const std::string whole = gzip_member(xml);
  ASSERT_EQ(read_gml([&] {
              const std::string p = dir.file("whole.gml.gz");
              std::ofstream(p, std::ios::binary) << whole;
              return p;
            }())
                .features.size(),
            300u);
  // Cut in the middle, and cut 4 bytes of the 8-byte trailer (the XML is complete, the file is not).
  for (size_t keep : {whole.size() / 2, whole.size() - 4}) {
    const std::string path = dir.file("cut" + std::to_string(keep) + ".gml.gz");
    std::ofstream(path, std::ios::binary) << whole.substr(0, keep);
    expect_refused(path, "truncated gzip file: it ends before its gzip trailer");
  }
}

}  // namespace
}  // namespace mc::io::test
