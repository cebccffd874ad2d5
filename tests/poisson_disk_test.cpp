// Bridson's Poisson disk: minimum distance, inside the disk, exact count, determinism.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "sampling/poisson_disk.h"
#include "sampling/poisson_disk_source.h"

TEST_CASE("Poisson disks of 1, 16, 36, 64 and 128 samples: count, inside the unit disk, every pair at least r apart") {
  for (int count : {1, 16, 36, 64, 128}) {
    for (std::uint32_t seed : {1u, 2u, 99u}) {
      const pn::PoissonDisk disk = pn::poisson_disk(count, seed);
      INFO(count << " samples, seed " << seed << ", r " << disk.min_distance);
      REQUIRE(disk.points.size() == static_cast<size_t>(count));
      double closest = 1e9;
      for (size_t i = 0; i < disk.points.size(); ++i) {
        const auto& p = disk.points[i];
        CHECK(std::hypot(p.x, p.y) <= 1.0 + 1e-6);
        for (size_t j = i + 1; j < disk.points.size(); ++j)
          closest = std::min(closest, std::hypot(double(p.x) - disk.points[j].x, double(p.y) - disk.points[j].y));
      }
      if (count > 1) CHECK(closest >= disk.min_distance * (1.0 - 1e-6));
      // Not degenerate: the spacing is within a factor of the densest packing's (about 1.9 / sqrt(n)).
      if (count >= 16) CHECK(disk.min_distance > 1.0 / std::sqrt(double(count)));
    }
  }
}

TEST_CASE("the same seed gives the same disk, another seed another one") {
  const auto a = pn::poisson_disk(64, 7), b = pn::poisson_disk(64, 7), c = pn::poisson_disk(64, 8);
  bool same = true, differ = false;
  for (size_t i = 0; i < a.points.size(); ++i) {
    same = same && a.points[i].x == b.points[i].x && a.points[i].y == b.points[i].y;
    differ = differ || a.points[i].x != c.points[i].x;
  }
  CHECK(same);
  CHECK(differ);
}

TEST_CASE("the GLSL constant has the count, the name and one vec2 per sample") {
  const auto disk = pn::poisson_disk(4, 3);
  const std::string glsl = pn::poisson_disk_glsl(disk, "PN_TEST_DISK", 3);
  CHECK(glsl.find("const vec2 PN_TEST_DISK[4] = vec2[](") != std::string::npos);
  size_t vec2s = 0;
  for (size_t at = glsl.find("    vec2("); at != std::string::npos; at = glsl.find("    vec2(", at + 1)) ++vec2s;
  CHECK(vec2s == 4);
}

TEST_CASE("negative: 0 or more than 4096 samples are refused") {
  CHECK_THROWS_WITH(pn::poisson_disk(0, 1), "Poisson disk of 0 samples: expected 1 to 4096");
  CHECK_THROWS_AS(pn::poisson_disk(5000, 1), pn::Error);
}

TEST_CASE("the GLSL constant's name must be an unreserved GLSL identifier (negative)") {
  const pn::PoissonDisk disk = pn::poisson_disk(4, 1u);
  CHECK(pn::poisson_disk_glsl(disk, "kDisk_4", 1u).find("const vec2 kDisk_4[4]") != std::string::npos);
  for (const char* bad : {"", "bad name;}", "4disk", "gl_Disk", "my__disk", "disk[2]"})
    CHECK_THROWS_WITH(pn::poisson_disk_glsl(disk, bad, 1u), Catch::Contains("expected a GLSL identifier"));
  for (const char* word : {"while", "int", "struct", "precise", "this", "goto", "vec3", "dmat2x4", "usampler2D", "image2D"})
    CHECK_THROWS_WITH(pn::poisson_disk_glsl(disk, word, 1u), Catch::Contains("a GLSL keyword or reserved word"));
  for (const char* fine : {"whiley", "vector", "matrix", "sampler", "images", "doMore"})
    CHECK_NOTHROW(pn::poisson_disk_glsl(disk, fine, 1u));
}

TEST_CASE("the disk in each language: its declaration, and each language's reserved words refused (negative)") {
  const pn::PoissonDisk disk = pn::poisson_disk(4, 1u);
  using pn::SourceLanguage;
  CHECK(pn::poisson_disk_source(disk, "kDisk", 1u, SourceLanguage::hlsl).find("static const float2 kDisk[4] = {") !=
        std::string::npos);
  CHECK(pn::poisson_disk_source(disk, "kDisk", 1u, SourceLanguage::msl).find("constant float2 kDisk[4] = {") !=
        std::string::npos);
  CHECK(pn::poisson_disk_source(disk, "kDisk", 1u, SourceLanguage::cpp).find("constexpr float kDisk[4][2] = {") !=
        std::string::npos);
  const std::pair<SourceLanguage, const char*> refused[] = {
      {SourceLanguage::hlsl, "cbuffer"}, {SourceLanguage::hlsl, "float3x4"}, {SourceLanguage::hlsl, "Texture2D"},
      {SourceLanguage::hlsl, "class"},   {SourceLanguage::msl, "constant"},  {SourceLanguage::msl, "half2"},
      {SourceLanguage::msl, "kernel"},   {SourceLanguage::cpp, "constexpr"}, {SourceLanguage::cpp, "and"}};
  for (const auto& [language, word] : refused)
    CHECK_THROWS_WITH(pn::poisson_disk_source(disk, word, 1u, language), Catch::Contains("keyword or reserved word"));
  for (SourceLanguage language : {SourceLanguage::glsl, SourceLanguage::hlsl, SourceLanguage::msl, SourceLanguage::cpp}) {
    CHECK_NOTHROW(pn::poisson_disk_source(disk, "disk_points", 1u, language));
    CHECK_THROWS_WITH(pn::poisson_disk_source(disk, "my__disk", 1u, language), Catch::Contains("identifier"));
  }
  CHECK_NOTHROW(pn::poisson_disk_source(disk, "gl_Disk", 1u, SourceLanguage::hlsl));  // gl_ is GLSL's alone
  CHECK_THROWS_WITH(pn::parse_source_language("java"), "--lang 'java': expected glsl, hlsl, msl or cpp");
}
