// The broken-input corpus (tests/io/bad/): file-level failures give one precise ReadError,
// per-object failures give precise problems while the rest of the file is still read.
#include "io_test_util.hpp"

namespace mc::io::test {
namespace {

struct FatalCase {
  const char* file;
  const char* message;  // after "<path>: "
};

class FatalInput : public ::testing::TestWithParam<FatalCase> {};

TEST_P(FatalInput, GivesPreciseReadError) {
  const auto& c = GetParam();
  const std::string path = bad_input(c.file);
  EXPECT_EQ(open_error(path), path + ": " + c.message);
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, FatalInput,
    ::testing::Values(
        FatalCase{
            "empty.city.json",
            "malformed JSON at byte 1: parse error at line 1, column 1: syntax error while parsing value - "
            "unexpected end of input; expected '[', '{', or a literal"},
        FatalCase{
            "truncated.city.json",
            "malformed JSON at byte 5001: parse error at line 1, column 5001: syntax error while parsing "
            "object key - invalid string: missing closing quote; last read: '\"documentnummer'; expected "
            "string literal"},
        FatalCase{
            "garbage.city.json",
            "malformed JSON at byte 1: parse error at line 1, column 1: syntax error while parsing value - "
            "invalid literal; last read: '\x89'"},
        FatalCase{"number_overflow.city.json", "malformed JSON at byte 120: number overflow parsing '1e999'"},
        FatalCase{"wrong_version.city.json",
                  "unsupported CityJSON version \"3.0\" (supported: 1.0, 1.1, 2.0)"},
        FatalCase{"wrong_version.city.jsonl",
                  "unsupported CityJSON version \"0.9\" (supported: 1.0, 1.1, 2.0)"},
        FatalCase{"missing_vertices.city.json", "missing required member \"vertices\""},
        FatalCase{"not_cityjson.city.json",
                  "not a CityJSON file (\"type\" is \"FeatureCollection\", expected \"CityJSON\")"},
        FatalCase{"cityobjects_array.city.json", "\"CityObjects\" must be an object, got an array"},
        FatalCase{"root_array.city.json", "the top-level JSON value is not an object"},
        FatalCase{"zero_scale.city.json", "invalid \"transform\": scale must be finite and non-zero"},
        FatalCase{"empty.city.jsonl", "empty file (a CityJSONSeq starts with a CityJSON header line)"},
        // Wrong types of the members every reader needs.
        FatalCase{"vertices_object.city.json", "\"vertices\" must be an array, got an object"},
        FatalCase{"version_number.city.json",
                  "\"version\" must be a string, got 2.0 (supported CityJSON versions: 1.0, 1.1, 2.0)"},
        FatalCase{"transform_string.city.json", "invalid \"transform\": not an object"},
        // Not JSON at all: NaN literals, invalid UTF-8, binary garbage and truncation of a sequence.
        FatalCase{"nan_literal.city.json",
                  "malformed JSON at byte 116: parse error at line 1, column 116: syntax error while parsing "
                  "value - "
                  "invalid literal; last read: '\"vertices\":[[N'"},
        FatalCase{
            "invalid_utf8.city.json",
            "malformed JSON at byte 104: parse error at line 1, column 104: syntax error while parsing "
            "object "
            "key - invalid string: ill-formed UTF-8 byte; last read: '\"b\xc3('; expected string literal"},
        FatalCase{
            "garbage.city.jsonl",
            "line 1: not a CityJSONSeq header (a CityJSONSeq starts with one CityJSON object on one line): "
            "parse error at line 1, column 1: syntax error while parsing value - unexpected end of input; "
            "expected '[', '{', or a literal"},
        FatalCase{
            "truncated.city.jsonl",
            "line 1: not a CityJSONSeq header (a CityJSONSeq starts with one CityJSON object on one line): "
            "parse error at line 1, column 72: syntax error while parsing object key - invalid string: "
            "missing closing quote; last read: '\"transl'; expected string literal"}),
    [](const auto& info) {
      std::string n = info.param.file;
      for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return n;
    });

TEST(BadInput, MissingFileIsReadError) {
  const std::string path = bad_input("does_not_exist.city.json");
  EXPECT_EQ(open_error(path), path + ": cannot open: No such file or directory");
}

// One feature per top-level object, in file order, each with its exact problems.
TEST(BadInput, BadObjectsAreReportedAndTheRestIsRead) {
  const auto w = read_all(bad_input("bad_objects.city.json"));
  EXPECT_EQ(w.problems,
            (std::vector<std::string>{"CityObject \"notanobject\" is not a JSON object (42); skipped",
                                      "vertex #9 is not an array of 3 numbers; faces using it are skipped"}));
  std::vector<std::string> ids;
  for (const auto& f : w.features) ids.push_back(f.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"good", "oob", "inf", "degenerate", "emptyring", "unknown",
                                           "wrongtypes", "badvertex", "orphan"}));
  std::map<std::string, BuildingInput> b;
  for (const auto& f : w.features) b[f.id] = extract_building(f, w.header);

  // The good building is complete: 6 faces with semantics, transform applied.
  ASSERT_EQ(b["good"].mesh.faces.size(), 6u);
  EXPECT_TRUE(b["good"].problems.empty()) << joined(b["good"].problems);
  EXPECT_EQ(b["good"].lod, "2.2");
  EXPECT_EQ(b["good"].mesh.semantic_labels,
            (std::vector<std::string>{"GroundSurface", "RoofSurface", "WallSurface"}));
  for (const auto& face : b["good"].mesh.faces) EXPECT_GE(face.semantic, 0);
  bool has_far_corner = false;
  for (const auto& v : b["good"].mesh.vertices) has_far_corner |= v == mc::Vec3(110, 210, 10);
  EXPECT_TRUE(has_far_corner);

  auto expect = [&](const std::string& id, size_t faces, const std::vector<std::string>& problems) {
    SCOPED_TRACE(id);
    EXPECT_EQ(b[id].mesh.faces.size(), faces);
    EXPECT_EQ(b[id].problems, problems);
  };
  expect("oob", 1,
         {"oob: geometry #0: vertex index 99 out of range (10 vertices)",
          "oob: geometry #0 (MultiSurface, LoD 2) surface 0: outer ring refers to a vertex that could not be "
          "read "
          "(-1); face skipped"});
  expect("inf", 1,
         {"inf: geometry #0: uses a vertex with non-finite coordinates (NaN or inf)",
          "inf: geometry #0 (MultiSurface, LoD 2) surface 0: outer ring has a vertex with non-finite "
          "coordinates (NaN "
          "or inf); face skipped"});
  expect(
      "degenerate", 2,
      {"degenerate: geometry #0 (MultiSurface, LoD 2) surface 0: outer ring has fewer than 3 distinct points "
       "(degenerate); face skipped",
       "degenerate: geometry #0 (MultiSurface, LoD 2) surface 1: hole 1 has fewer than 3 distinct points "
       "(degenerate); hole skipped"});
  expect(
      "emptyring", 1,
      {"emptyring: geometry #0 (MultiSurface, LoD 2) surface 0: outer ring has fewer than 3 distinct points "
       "(degenerate); face skipped"});
  expect("unknown", 1, {"unknown: geometry #0: unknown geometry type \"Blob\"; skipped"});
  expect("wrongtypes", 0,
         {"wrongtypes: geometry #0: \"abc\" is not a vertex index",
          "wrongtypes: geometry #0 (MultiSurface, LoD 2): malformed boundaries (expected an array); skipped",
          "wrongtypes: no usable faces at LoD 2"});
  expect("badvertex", 1,
         {"badvertex: geometry #0: uses a vertex with non-finite coordinates (NaN or inf)",
          "badvertex: geometry #0 (MultiSurface, LoD 2) surface 0: outer ring has a vertex with non-finite "
          "coordinates (NaN or inf); face skipped"});
  // An object whose parent is missing becomes its own top-level feature (not a building).
  const auto& orphan = w.features.back();
  EXPECT_EQ(orphan.problems, (std::vector<std::string>{"orphan: parent \"nosuch\" does not exist"}));
  EXPECT_FALSE(is_building(orphan));
  EXPECT_EQ(b["degenerate"].mesh.faces[0].rings.size(), 1u);  // the bad hole is dropped, the face kept
}

TEST(BadInput, BadSequenceLinesAreSkipped) {
  const std::string path = bad_input("bad_lines.city.jsonl");
  const auto w = read_all(path);
  EXPECT_EQ(
      w.problems,
      (std::vector<std::string>{
          path + ": line 3: malformed JSON (parse error at line 1, column 72: syntax error while parsing "
                 "value - "
                 "invalid string: missing closing quote; last read: '\"Buil'); line skipped",
          path + ": line 4: \"type\" is \"CityJSON\", expected \"CityJSONFeature\"; line skipped",
          path +
              ": line 6: malformed JSON (parse error at line 1, column 2: syntax error while parsing value - "
              "invalid literal; last read: 'no'); line skipped"}));
  ASSERT_EQ(w.features.size(), 3u);
  EXPECT_EQ(w.features[0].id, "first");
  EXPECT_EQ(w.features[1].id, "oob");
  EXPECT_EQ(w.features[2].id, "last");
  EXPECT_EQ(w.features[1].problems,
            (std::vector<std::string>{"oob: geometry #0: vertex index 7 out of range (3 vertices)"}));
  EXPECT_EQ(extract_building(w.features[2], w.header).mesh.faces.size(), 1u);
}

// Feature lines with missing or mistyped members: each feature keeps a precise problem, lines that
// are not objects are skipped, and the good feature after them is read.
TEST(BadInput, BadFeatureMembersAreReportedPerFeature) {
  const std::string path = bad_input("bad_features.city.jsonl");
  const auto w = read_all(path);
  EXPECT_EQ(w.problems, (std::vector<std::string>{path + ": line 6: not a JSON object; line skipped"}));
  std::vector<std::string> ids;
  for (const auto& f : w.features) ids.push_back(f.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"novertices", "vertices_wrong_type", "noid", "other", "good"}));
  EXPECT_EQ(w.features[0].problems,
            (std::vector<std::string>{
                "novertices: feature line 2 has no \"vertices\" array; its geometry cannot be read",
                "novertices: geometry #0: vertex index 0 out of range (0 vertices)",
                "novertices: geometry #0: vertex index 1 out of range (0 vertices)",
                "novertices: geometry #0: vertex index 2 out of range (0 vertices)"}));
  EXPECT_EQ(
      w.features[1].problems,
      (std::vector<std::string>{
          "vertices_wrong_type: feature line 3 has no \"vertices\" array; its geometry cannot be read"}));
  EXPECT_EQ(
      w.features[2].problems,
      (std::vector<std::string>{"noid: feature line 4 has no valid \"id\"; using this top-level object"}));
  EXPECT_EQ(
      w.features[3].problems,
      (std::vector<std::string>{"other: feature line 5 has no valid \"id\"; using this top-level object"}));
  EXPECT_TRUE(w.features[4].problems.empty());
  EXPECT_EQ(extract_building(w.features[4], w.header).mesh.faces.size(), 1u);
  EXPECT_TRUE(extract_building(w.features[0], w.header).mesh.empty());
}

// 100 000 nested arrays (generated, not committed): once a stack overflow in the serializer that
// reports a bad vertex reference. A .city.json is refused as a whole (the scan stops at the
// limit); in a sequence only the line is skipped.
TEST(BadInput, DeepNestingIsRefusedWithoutRecursion) {
  ScratchDir dir;
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string doc = dir.file("deep.city.json");
  std::ofstream(doc)
      << R"({"type":"CityJSON","version":"2.0","transform":{"scale":[1,1,1],"translate":[0,0,0]},)"
      << R"("CityObjects":{"deep":{"type":"Building","geometry":[{"type":"MultiSolid","lod":"2",)"
      << R"("boundaries":)" << deep << R"(}]}},"vertices":[[0,0,0]]})";
  EXPECT_EQ(open_error(doc), doc + ": JSON nested deeper than 512 levels at byte 690");
  const std::string seq = dir.file("deep.city.jsonl");
  std::ofstream(seq)
      << R"({"type":"CityJSON","version":"2.0","transform":{"scale":[1,1,1],"translate":[0,0,0]},)"
      << R"("CityObjects":{},"vertices":[]})"
      << "\n"
      << R"({"type":"CityJSONFeature","id":"deep","CityObjects":{"deep":{"type":"Building",)"
      << R"("attributes":{"a":)" << deep << R"(}}},"vertices":[]})"
      << "\n"
      << R"({"type":"CityJSONFeature","id":"ok","CityObjects":{"ok":{"type":"Building"}},"vertices":[]})"
      << "\n";
  const auto w = read_all(seq);
  EXPECT_EQ(w.problems,
            (std::vector<std::string>{seq + ": line 2: JSON nested deeper than 512 levels; line skipped"}));
  ASSERT_EQ(w.features.size(), 1u);
  EXPECT_EQ(w.features[0].id, "ok");
}

// Random corruptions of a real file: never a crash, only ReadError or problems.
TEST(BadInput, CorruptedBytesNeverCrash) {
  const std::string src = project_data("3dbag/3dbag_b2.city.json");
  std::ifstream in(src, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(text.size(), 1000u);
  ScratchDir dir;
  uint64_t state = 12345;
  auto rnd = [&] { return state = state * 6364136223846793005ULL + 1442695040888963407ULL, state >> 33; };
  int fatal = 0, read = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::string t = text;
    for (int k = 0; k < 1 + trial % 5; ++k) t[rnd() % t.size()] = "0123456789[]{},:\"-e."[rnd() % 20];
    const std::string path = dir.file("c" + std::to_string(trial) + ".city.json");
    std::ofstream(path, std::ios::binary) << t;
    try {
      auto w = read_all(path);
      for (const auto& f : w.features) extract_building(f, w.header);
      ++read;
    } catch (const ReadError&) { ++fatal; }
  }
  EXPECT_EQ(fatal + read, 200);
  EXPECT_GT(fatal, 0);
  EXPECT_GT(read, 0);
}

}  // namespace
}  // namespace mc::io::test
