// Writer behaviour beyond the round trips: atomicity, version keeping, quantisation, extras.
#include "io_test_util.hpp"

namespace mc::io::test {
namespace {

using nlohmann::json;

Header header_2_0() {
  Header h;
  h.version = "2.0";
  h.root = {{"type", "CityJSON"},
            {"version", "2.0"},
            {"transform", {{"scale", {0.01, 0.01, 0.01}}, {"translate", {100, 200, 0}}}},
            {"metadata", {{"title", "t"}}}};
  return h;
}

Feature triangle(const std::string& id, double shift = 0) {
  Feature f;
  f.id = id;
  f.objects = {{id,
                {{"type", "Building"},
                 {"attributes", {{"h", 3}}},
                 {"geometry", json::array({{{"type", "MultiSurface"},
                                            {"lod", "2"},
                                            {"boundaries", json::parse("[[[0,1,2]]]")}}})}}}};
  f.vertices = {{100 + shift, 200, 0}, {101.234, 200, 0}, {100, 201.006, 5.5}};
  return f;
}

TEST(CityJsonWriter, WithoutCloseNothingAppearsAndNoTempIsLeft) {
  ScratchDir dir;
  const std::string out = dir.file("a.city.json");
  {
    CityJsonWriter w(out, header_2_0());
    w.write(triangle("x"));
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(dir.entries(), 0u);
}

TEST(CityJsonWriter, FailedRewriteKeepsThePreviousOutput) {
  ScratchDir dir;
  const std::string out = dir.file("a.city.jsonl");
  {
    CityJsonWriter w(out, header_2_0());
    w.write(triangle("old"));
    w.close();
  }
  try {
    CityJsonWriter w(out, header_2_0());
    w.write(triangle("new"));
    throw std::runtime_error("job failed");
  } catch (const std::runtime_error&) {}
  const auto r = read_all(out);
  ASSERT_EQ(r.features.size(), 1u);
  EXPECT_EQ(r.features[0].id, "old");
  EXPECT_EQ(dir.entries(), 1u);
}

TEST(CityJsonWriter, QuantisesWithTheHeaderTransformAndOffsetsIndices) {
  ScratchDir dir;
  const std::string out = dir.file("b.city.json");
  CityJsonWriter w(out, header_2_0());
  w.write(triangle("x"));
  w.write(triangle("y", 0.5));
  w.close();
  EXPECT_EQ(w.features_written(), 2u);
  std::ifstream in(out);
  const json doc = json::parse(in);
  EXPECT_EQ(doc["version"], "2.0");
  EXPECT_EQ(doc["metadata"]["title"], "t");
  EXPECT_EQ(doc["vertices"], json::parse("[[0,0,0],[123,0,0],[0,101,550],[50,0,0],[123,0,0],[0,101,550]]"));
  EXPECT_EQ(doc["CityObjects"]["y"]["geometry"][0]["boundaries"], json::parse("[[[3,4,5]]]"));
  EXPECT_EQ(doc["CityObjects"]["x"]["attributes"]["h"], 3);
}

TEST(CityJsonWriter, Version10WithoutTransformWritesFloats) {
  ScratchDir dir;
  Header h;
  h.version = "1.0";
  h.root = {{"type", "CityJSON"}, {"version", "1.0"}};
  const std::string out = dir.file("c.city.json");
  CityJsonWriter w(out, h);
  w.write(triangle("x"));
  w.close();
  std::ifstream in(out);
  const json doc = json::parse(in);
  EXPECT_EQ(doc["version"], "1.0");
  EXPECT_FALSE(doc.contains("transform"));
  EXPECT_EQ(doc["vertices"][1][0].get<double>(), 101.234);
}

TEST(CityJsonWriter, SequenceKeepsFeatureMembersDocumentCountsThem) {
  ScratchDir dir;
  Feature f = triangle("x");
  f.extra = {{"appearance", {{"materials", json::array({{{"name", "m"}}})}}}};
  const std::string seq = dir.file("d.city.jsonl"), doc = dir.file("d.city.json");
  {
    CityJsonWriter w(seq, header_2_0());
    w.write(f);
    w.close();
    EXPECT_EQ(w.dropped_extras(), 0u);
  }
  {
    CityJsonWriter w(doc, header_2_0());
    w.write(f);
    w.close();
    EXPECT_EQ(w.dropped_extras(), 1u);
  }
  const auto r = read_all(seq);
  ASSERT_EQ(r.features.size(), 1u);
  EXPECT_EQ(r.features[0].extra, f.extra);
}

TEST(CityJsonWriter, MissingDirectoryIsWriteError) {
  EXPECT_THROW(CityJsonWriter(std::string(MC_BINARY_DIR) + "/no/such/dir/x.city.json", header_2_0()),
               WriteError);
}

}  // namespace
}  // namespace mc::io::test
