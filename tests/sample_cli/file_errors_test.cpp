// edgewise-sample's file errors: each ends with exit status 1 and one line on standard error
// naming the file and the cause, never a crash, and leaves no result file behind. An output that
// would overwrite an input is a command-line mistake (status 2).
#include <gtest/gtest.h>

#include <OpenImageIO/typedesc.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/temp_directory.hpp"
#include "test_files.hpp"
#include "tool_run.hpp"

namespace edgewise::sample_cli_test {
namespace {

using scene::test::TempDirectory;

::testing::AssertionResult fails_with(const ToolRun& run, int status, const std::string& message) {
  const auto failure = [&] {
    return ::testing::AssertionFailure()
           << "exit status " << run.status << ", stderr '" << run.err << "'; expected status "
           << status << " and '" << message << "'";
  };
  if (run.status != status) return failure();
  const std::string prefix = "edgewise-sample: ";
  const bool one_line = !run.err.empty() && run.err.find('\n') == run.err.size() - 1;
  if (!one_line || run.err.rfind(prefix, 0) != 0 || run.err.find(message) == std::string::npos) {
    return failure();
  }
  return ::testing::AssertionSuccess();
}

// A valid texture and query file in a fresh directory; each test breaks one thing.
class SampleToolFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::vector<std::uint8_t> texels(4 * 4 * 3, 128);
    write_image(image_path, 4, 3, 4, OIIO::TypeDesc::UINT8, texels.data());
    const TextureQuery query{0.5f, 0.5f, 0.1f, 0.0f, 0.0f, 0.1f};
    write_queries(queries_path, {&query, 1});
  }

  ToolRun run(const std::string& texture, const std::string& query_file, const std::string& out,
              const std::optional<std::string>& piped = std::nullopt) const {
    return run_sample_tool(
        {"--texture", texture, "--filter", "trilinear", "--queries", query_file, "--out", out}, d,
        piped);
  }

  const TempDirectory dir;
  const std::string d = dir.path().string();
  const std::string image_path = d + "/texture.png";
  const std::string queries_path = d + "/queries.bin";
  const std::string results_path = d + "/results.bin";
};

TEST_F(SampleToolFiles, TheValidFilesWork) {
  const ToolRun result = run(image_path, queries_path, results_path);
  EXPECT_EQ(result.status, 0) << result.summary();
  EXPECT_EQ(std::filesystem::file_size(results_path), 16u);
}

TEST_F(SampleToolFiles, MissingImage) {
  EXPECT_TRUE(fails_with(run(d + "/no_such.png", queries_path, results_path), 1,
                         "no_such.png: cannot open: No such file or directory"));
  EXPECT_FALSE(std::filesystem::exists(results_path)) << "a failed run leaves no result file";
}

TEST_F(SampleToolFiles, ImageIsADirectory) {
  EXPECT_TRUE(
      fails_with(run(d, queries_path, results_path), 1, d + ": cannot open: Is a directory"));
}

TEST_F(SampleToolFiles, ImageIsNotAnImage) {
  write_bytes(d + "/notes.png", "not a PNG\n");
  EXPECT_TRUE(fails_with(run(d + "/notes.png", queries_path, results_path), 1,
                         "notes.png: cannot read image"));
  EXPECT_FALSE(std::filesystem::exists(results_path)) << "a failed run leaves no result file";
}

TEST_F(SampleToolFiles, ImageTooWideForATexture) {
  const std::vector<std::uint8_t> row(32769, 7);
  write_image(d + "/wide.png", 32769, 1, 1, OIIO::TypeDesc::UINT8, row.data());
  EXPECT_TRUE(fails_with(run(d + "/wide.png", queries_path, results_path), 1,
                         "wide.png: 32769x1 is not a texture size (1..32768 texels a side)"));
}

TEST_F(SampleToolFiles, MissingQueries) {
  EXPECT_TRUE(fails_with(run(image_path, d + "/no_such.bin", results_path), 1,
                         "no_such.bin: cannot open: No such file or directory"));
}

TEST_F(SampleToolFiles, QueriesNotWholeRecords) {
  write_bytes(queries_path, std::string(25, '\0'));
  EXPECT_TRUE(fails_with(run(image_path, queries_path, results_path), 1,
                         "queries.bin: 25 bytes is not a whole number of 24-byte query records"));
  EXPECT_FALSE(std::filesystem::exists(results_path)) << "a failed run leaves no result file";
}

TEST_F(SampleToolFiles, PipedQueriesEndInsideARecord) {
  write_bytes(queries_path, std::string(49, '\0'));
  EXPECT_TRUE(fails_with(run(image_path, "/dev/stdin", results_path, queries_path), 1,
                         "/dev/stdin: ends inside a query record (1 byte left over"));
  EXPECT_FALSE(std::filesystem::exists(results_path)) << "a partial result file is removed";
}

TEST_F(SampleToolFiles, OutputDirectoryMissing) {
  EXPECT_TRUE(fails_with(run(image_path, queries_path, d + "/no_such_dir/results.bin"), 1,
                         "results.bin: cannot write: No such file or directory"));
}

TEST_F(SampleToolFiles, OutputDeviceFull) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  EXPECT_TRUE(fails_with(run(image_path, queries_path, "/dev/full"), 1,
                         "/dev/full: cannot write: No space left"));
}

TEST_F(SampleToolFiles, OutputOverAnInputIsRefused) {
  // The same file under another name is caught too.
  EXPECT_TRUE(
      fails_with(run(image_path, queries_path, d + "/./queries.bin"), 2, "is the input file"));
  EXPECT_EQ(std::filesystem::file_size(queries_path), 24u) << "the query file is untouched";
  EXPECT_TRUE(fails_with(run(image_path, queries_path, image_path), 2, "is the input file"));
}

}  // namespace
}  // namespace edgewise::sample_cli_test
