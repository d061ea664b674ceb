// OFF/OBJ: the paper's samples (OFF and NOFF, per-face colours), comments, round trips with
// colours, semantics and holes, and precise errors.
#include "io/off_obj.hpp"

#include "io_test_util.hpp"

namespace mc::io::test {
namespace {

TEST(Off, ReadsEveryPaperSample) {
  if (!have_shared()) GTEST_SKIP() << "no " << shared_dir();
  size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(shared_dir() + "/morphcut-samples")) {
    if (e.path().extension() != ".off") continue;
    SCOPED_TRACE(e.path().string());
    std::ifstream in(e.path());
    std::string header;
    size_t nv = 0, nf = 0;
    in >> header >> nv >> nf;
    const auto mesh = read_off(e.path().string());
    EXPECT_EQ(mesh.vertices.size(), nv);
    EXPECT_EQ(mesh.faces.size(), nf);
    ++files;
  }
  EXPECT_EQ(files, 32u);  // 16 inputs + 16 reconstructions (sample24 has neither)
}

TEST(Off, ReadsNoffAndColouredFaces) {
  const auto noff = read_off(project_data("meshes/00007_noff.off"));
  EXPECT_EQ(noff.vertices.size(), 439u);
  EXPECT_EQ(noff.faces.size(), 190u);
  EXPECT_EQ(noff.vertices[0], mc::Vec3(83.36668, 137.2155, 4.064529));  // normals ignored
  EXPECT_EQ(noff.faces.back().rings[0], (std::vector<uint32_t>{437, 438, 431, 432, 433, 434, 435, 436}));
}

TEST(Off, CommentsBlankLinesAndCountsOnTheHeaderLine) {
  ScratchDir dir;
  const std::string p = dir.file("c.off");
  std::ofstream(p) << "# a comment\n\nCOFF 4 2 0 # counts here\n0 0 0 255 0 0 255\n1 0 0 0 0 0 255\n"
                      "\n0 1 0 1 1 1 1\n0 0 1 2 2 2 2\n3 0 1 2 10 20 30\n2 0 1\n";
  std::vector<std::string> problems;
  const auto m = read_off(p, &problems);
  EXPECT_EQ(m.vertices.size(), 4u);
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.faces[0].rings[0], (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(problems, (std::vector<std::string>{p + ":10: face with fewer than 3 vertices skipped"}));
}

TEST(Off, BadFilesGivePreciseErrors) {
  auto error = [](const std::string& path) -> std::string {
    try {
      read_off(path);
    } catch (const ReadError& e) { return e.what(); }
    return "";
  };
  const std::string a = bad_input("index_out_of_range.off"), b = bad_input("truncated.off"),
                    c = bad_input("nan.off");
  EXPECT_EQ(error(a), a + ":7: vertex index 9 out of range (4 vertices)");
  EXPECT_EQ(error(b), b + ": file ends after 3 of 4 vertices");
  EXPECT_EQ(error(c), c + ":4: non-finite coordinate \"nan\"");
  EXPECT_EQ(error(bad_input("bad_objects.city.json")),
            bad_input("bad_objects.city.json") + ":1: not an OFF file (header \"{\")");
}

mc::PolygonMesh square_with_hole() {
  mc::PolygonMesh m;
  for (auto [x, y] : {std::pair{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {4, 6}, {6, 6}, {6, 4}})
    m.vertices.emplace_back(x, y, 0.1);
  m.faces.push_back({{{0, 1, 2, 3}, {4, 5, 6, 7}}, m.label_index("GroundSurface")});
  m.faces.push_back({{{0, 1, 5}}, -1});
  m.faces.push_back({{{1, 2, 6}}, m.label_index("WallSurface")});
  return m;
}

TEST(Off, WriteReadRoundTripWithColoursAndBridgedHoles) {
  ScratchDir dir;
  const auto m = square_with_hole();
  const std::string p = dir.file("m.off");
  write_off(p, m, {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}});
  const auto r = read_off(p);
  EXPECT_EQ(r.vertices, m.vertices);
  ASSERT_EQ(r.faces.size(), 3u);
  // The holed face is one ring: outer 0..3 and hole 4..7 joined through the bridge 0-4.
  EXPECT_EQ(r.faces[0].rings[0], (std::vector<uint32_t>{0, 4, 5, 6, 7, 4, 0, 1, 2, 3}));
  EXPECT_EQ(r.faces[1].rings[0], m.faces[1].rings[0]);
  std::ifstream in(p);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("3 1 2 6  0 0 255\n"), std::string::npos);
  EXPECT_THROW(write_off(p, m, {{1, 2, 3}}), WriteError);  // colour count mismatch
}

TEST(Obj, WriteReadRoundTripKeepsSemantics) {
  ScratchDir dir;
  const auto m = square_with_hole();
  const std::string p = dir.file("m.obj");
  write_obj(p, m);
  const auto r = read_obj(p);
  EXPECT_EQ(r.vertices, m.vertices);
  ASSERT_EQ(r.faces.size(), 3u);
  EXPECT_EQ(r.semantic_labels, m.semantic_labels);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(r.faces[i].semantic, m.faces[i].semantic) << i;
  EXPECT_EQ(dir.entries(), 1u);  // no temp file left
}

TEST(Obj, SlashesAndNegativeIndices) {
  ScratchDir dir;
  const std::string p = dir.file("n.obj");
  std::ofstream(p)
      << "o x\nv 0 0 0\nv 1 0 0\nvt 0 0\nvn 0 0 1\nv 0 1 0 1.0\nf 1/1/1 2//1 3\nf -3 -2 -1\nf 1 2 4\n";
  try {
    read_obj(p);
    FAIL() << "expected ReadError";
  } catch (const ReadError& e) {
    EXPECT_EQ(std::string(e.what()), p + ":9: vertex reference 4 out of range (3 vertices so far)");
  }
  std::ofstream(p) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1 2//1 3\nf -3 -2 -1\n";
  const auto m = read_obj(p);
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.faces[0].rings[0], m.faces[1].rings[0]);
}

TEST(Off, WritingIntoAMissingDirectoryIsWriteError) {
  EXPECT_THROW(write_off(std::string(MC_BINARY_DIR) + "/no/such/dir/m.off", square_with_hole()), WriteError);
}

}  // namespace
}  // namespace mc::io::test
