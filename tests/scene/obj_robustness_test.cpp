// Random bytes and mutated valid files through the OBJ loader: every input must give either a
// valid mesh or an error message, never a crash, a hang or (under the sanitizers) undefined
// behaviour. The generator is seeded, so a failure replays.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "obj_files.hpp"
#include "random.hpp"
#include "scene/obj_loader.hpp"
#include "temp_directory.hpp"

namespace edgewise::scene::test {
namespace {

using edgewise::test::Random;

// Bytes OBJ and MTL files are made of, so that random text often reaches deep into the parser.
constexpr std::string_view kObjAlphabet = "vtnfl /-+.e0123456789#\n\r\tgosupmKdN";

// Values at the edges of what the loader accepts, spliced in place of numbers.
constexpr std::string_view kExtremeValues[] = {
    "0",           "-0",  "-1",  "1e38",       "1e39",       "-3.5e38",     "1e-45",
    "1e-400",      "nan", "inf", "2147483647", "2147483648", "-2147483648", "4294967295",
    "99999999999", ".",   "-",   "1e",         "0x10",       "1/1/1/1",     "//",
    "1//",         ""};

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f && c != '\\') {
      out += c;
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

char random_byte(Random& random) {
  if (random.chance(0.6)) {
    return kObjAlphabet[static_cast<std::size_t>(
        random.integer(0, static_cast<std::int64_t>(kObjAlphabet.size()) - 1))];
  }
  return static_cast<char>(random.integer(0, 255));
}

std::size_t random_position(Random& random, const std::string& text) {
  return static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(text.size())));
}

// One to four edits: a byte replaced, inserted or deleted, a line repeated, or a number replaced
// by an extreme value.
std::string mutate(std::string text, Random& random) {
  const int edits = static_cast<int>(random.integer(1, 4));
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = random_position(random, text);
    switch (random.integer(0, 4)) {
      case 0:
        if (at < text.size()) text[at] = random_byte(random);
        break;
      case 1:
        text.insert(at, 1, random_byte(random));
        break;
      case 2:
        if (at < text.size()) text.erase(at, static_cast<std::size_t>(random.integer(1, 8)));
        break;
      case 3: {
        const std::size_t start = text.rfind('\n', at == 0 ? 0 : at - 1);
        const std::size_t line_start = start == std::string::npos ? 0 : start + 1;
        const std::size_t line_end = text.find('\n', at);
        if (line_end != std::string::npos) {
          text.insert(line_end + 1, text.substr(line_start, line_end + 1 - line_start));
        }
        break;
      }
      default: {
        const std::size_t number = text.find_first_of("-0123456789", at);
        if (number == std::string::npos) break;
        const std::size_t end = text.find_first_of(" \t\r\n", number);
        const auto& value = kExtremeValues[random.integer(0, std::size(kExtremeValues) - 1)];
        text.replace(number, (end == std::string::npos ? text.size() : end) - number, value);
        break;
      }
    }
  }
  return text;
}

struct Outcomes {
  int accepted = 0;
  int rejected = 0;
  ~Outcomes() { std::printf("%d inputs accepted, %d rejected\n", accepted, rejected); }
};

// A result is a valid, non-empty mesh or a message naming the input; anything else fails with
// the input printed so that it can be replayed.
void check_outcome(const MeshResult& result, std::string_view name, std::string_view input,
                   Outcomes& outcomes) {
  if (result.ok()) {
    ++outcomes.accepted;
    const auto problem = validate(result.mesh());
    EXPECT_FALSE(problem.has_value()) << *problem << "\ninput: " << escaped(input);
    EXPECT_GT(triangle_count(result.mesh()), 0u) << "input: " << escaped(input);
  } else {
    ++outcomes.rejected;
    EXPECT_TRUE(result.error().starts_with(std::string(name) + ": ") &&
                result.error().size() > name.size() + 2)
        << "error: " << result.error() << "\ninput: " << escaped(input);
  }
}

TEST(ObjRobustness, RandomBytes) {
  Random random(20240611);
  Outcomes outcomes;
  for (int i = 0; i < 20000; ++i) {
    std::string text(static_cast<std::size_t>(random.integer(0, 160)), '\0');
    for (char& c : text)
      c = random_byte(random);
    check_outcome(parse_obj(text, "random"), "random", text, outcomes);
  }
  // Random bytes almost never make a face whose indices all exist.
  EXPECT_GT(outcomes.rejected, 19000);
}

TEST(ObjRobustness, RandomFaceStatements) {
  // Well-formed statements in random order with indices near the valid range: many files pass,
  // many name an element that does not exist (yet, or at all).
  Random random(77);
  Outcomes outcomes;
  const auto index = [&random] {
    if (random.chance(0.02)) return std::string("0");
    return std::to_string(random.chance(0.3) ? random.integer(-2, -1) : random.integer(1, 3));
  };
  for (int i = 0; i < 5000; ++i) {
    std::string text = "v 0 0 0\nv 1 0 0\n";
    const int lines = static_cast<int>(random.integer(1, 10));
    for (int l = 0; l < lines; ++l) {
      switch (random.integer(0, 3)) {
        case 0:
          text += "v 0 1 2\n";
          break;
        case 1:
          text += "vt 0.5 0.5\n";
          break;
        case 2:
          text += "vn 0 0 1\n";
          break;
        default: {
          text += "f";
          const int corners = random.chance(0.05) ? 2 : static_cast<int>(random.integer(3, 6));
          const std::int64_t form = random.integer(0, 3);  // v, v/t, v//n, v/t/n
          for (int k = 0; k < corners; ++k) {
            text += ' ';
            text += index();
            if (form == 1 || form == 3) text.append("/").append(index());
            if (form == 2) text += '/';
            if (form >= 2) text.append("/").append(index());
          }
          text += '\n';
        }
      }
    }
    check_outcome(parse_obj(text, "faces"), "faces", text, outcomes);
  }
  EXPECT_GT(outcomes.accepted, 100);
  EXPECT_GT(outcomes.rejected, 100);
}

TEST(ObjRobustness, MutatedValidFiles) {
  Random random(4242);
  Outcomes outcomes;
  const std::string seeds[] = {
      std::string(kCubeObj),
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\nf -3/-1/-1 -2/-1/-1 -1/-1/-1\n",
      "v -8 -9 0\nv -10 -6 0\nv -10 -10 0\nv -6 -10 0\nv -6 -6 0\nf 1 2 3 4 5\n",
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 1 1 1 1\nf 1 2 3\nf 2 4 3\n"};
  for (int i = 0; i < 20000; ++i) {
    const std::string text = mutate(seeds[i % std::size(seeds)], random);
    check_outcome(parse_obj(text, "mutated"), "mutated", text, outcomes);
  }
  EXPECT_GT(outcomes.accepted, 400);
  EXPECT_GT(outcomes.rejected, 400);
}

// Through files, with the MTL file mutated too (tinyobjloader's MTL reader has no line check).
TEST(ObjRobustness, MutatedFilesWithMaterials) {
  const TempDirectory directory;
  Random random(99);
  Outcomes outcomes;
  for (int i = 0; i < 60; ++i) {
    const std::string obj = mutate(std::string(kTwoMaterialsObj), random);
    const std::string mtl = mutate(std::string(kColoursMtl), random);
    directory.write("colours.mtl", mtl);
    const std::string path = directory.write("square.obj", obj);
    check_outcome(load_obj(path), path, obj + "\n--- colours.mtl:\n" + mtl, outcomes);
  }
  EXPECT_GT(outcomes.accepted, 5);
  EXPECT_GT(outcomes.rejected, 5);
}

}  // namespace
}  // namespace edgewise::scene::test
