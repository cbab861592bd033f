// `exactgeo predicate`: batch semantics, errors, JSON, exactness through the text path,
// and robustness against arbitrary input.

#include "cli/predicate_command.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::cli {
namespace {

struct Outcome {
  ExitCode code;
  std::string out;
  std::string err;
};

Outcome run(PredicateKind kind, const std::string& input, bool json = false,
            Arithmetic arithmetic = Arithmetic::exact) {
  PredicateOptions options;
  options.kind = kind;
  options.json = json;
  options.arithmetic = arithmetic;
  std::istringstream in(input);
  std::ostringstream out, err;
  const ExitCode code = run_predicate(options, in, "<stdin>", out, err);
  return {code, out.str(), err.str()};
}

TEST(PredicateCommand, Orient3dAnswersOnePerLine) {
  const Outcome r = run(PredicateKind::orient3d,
                        "0 0 0 1 0 0 0 1 0 0 0 1\n"
                        "# comment\n\n"
                        "0,0,0, 0,1,0, 1,0,0, 0,0,1\n"
                        "0 0 0 1 0 0 0 1 0 0x1p-1074 0x1p-1074 0\n");
  EXPECT_EQ(r.code, ExitCode::success);
  EXPECT_EQ(r.out, "1\n-1\n0\n");
  EXPECT_EQ(r.err, "");
}

TEST(PredicateCommand, RayPatchAnswers) {
  const std::string saddle = " 0 0 0  1 0 0  1 1 1  0 1 0\n";  // p(u,v) = (u, v, uv)
  const Outcome r = run(PredicateKind::ray_patch,
                        "0.3 0.3 5  0 0 -1" + saddle +        // crosses once
                            "3 3 5  0 0 -1" + saddle +        // misses
                            "0.5 0.5 0.25  0 0 1" + saddle +  // origin on the patch
                            "0.5 0 5  0 0 -1" + saddle);      // through a boundary edge
  EXPECT_EQ(r.code, ExitCode::success);
  EXPECT_EQ(r.out, "odd\neven\non\ndegenerate\n");
}

TEST(PredicateCommand, JsonIsOneObject) {
  const Outcome r =
      run(PredicateKind::orient3d, "0 0 0 1 0 0 0 1 0 0 0 1\n0 0 0 0 1 0 1 0 0 0 0 1\n",
          /*json=*/true);
  EXPECT_EQ(r.code, ExitCode::success);
  EXPECT_EQ(r.out,
            "{\"predicate\": \"orient3d\", \"arithmetic\": \"exact\", \"count\": 2, "
            "\"results\": [1, -1]}\n");
  const Outcome p = run(PredicateKind::ray_patch, "0.3 0.3 5 0 0 -1 0 0 0 1 0 0 1 1 1 0 1 0\n",
                        true, Arithmetic::rational);
  EXPECT_EQ(p.out,
            "{\"predicate\": \"ray-patch\", \"arithmetic\": \"rational\", \"count\": 1, "
            "\"results\": [\"odd\"]}\n");
}

TEST(PredicateCommand, BadInputNamesTheLineAndPrintsNothing) {
  struct Case {
    PredicateKind kind;
    std::string input;
    std::string message;
  };
  const Case cases[] = {
      {PredicateKind::orient3d, "0 0 0 1 0 0 0 1 0 0 0 1\n1 2 3\n",
       "<stdin>:2: expected 12 numbers for orient3d, found 3"},
      {PredicateKind::orient3d, "0 0 0 1 0 0 0 1 0 0 0 nan\n",
       "<stdin>:1: field 12: 'nan' is not a number"},
      {PredicateKind::orient3d, "\n\n0 0 0 1 0 0 0 1 0 0 0 inf\n",
       "<stdin>:3: field 12: 'inf' is not a number"},
      {PredicateKind::orient3d, "0 0 0 1 0 0 0 1 0 0 0 1e999\n",
       "<stdin>:1: field 12: '1e999' is outside the range of double"},
      {PredicateKind::orient3d, "0 0 0 1 0 0 0 1 0 0 0,,1\n", "<stdin>:1: field 12 is empty"},
      {PredicateKind::ray_patch, "0 0 0 0 0 0 0 0 0 1 0 0 1 1 1 0 1 0\n",
       "<stdin>:1: the ray direction is zero"},
  };
  for (const Case& c : cases) {
    const Outcome r = run(c.kind, c.input);
    EXPECT_EQ(r.code, ExitCode::input_error) << c.input;
    EXPECT_EQ(r.out, "") << "partial output for " << c.input;
    EXPECT_EQ(r.err, "exactgeo predicate: " + c.message + "\n");
  }
}

TEST(PredicateCommand, EmptyInputIsNoCases) {
  EXPECT_EQ(run(PredicateKind::orient3d, "").out, "");
  EXPECT_EQ(
      run(PredicateKind::orient3d, "", true).out,
      "{\"predicate\": \"orient3d\", \"arithmetic\": \"exact\", \"count\": 0, \"results\": []}\n");
}

std::string hexfloat_line(const std::array<Point3, 4>& p) {
  std::string line;
  char buf[32];
  for (const Point3& q : p) {
    for (const double x : q) {
      std::snprintf(buf, sizeof buf, "%a ", x);
      line += buf;
    }
  }
  return line + "\n";
}

TEST(PredicateCommand, Orient3dThroughTextAgreesWithOracleOnAdversarialInput) {
  testing::Rng rng = testing::seeded_engine("cli-orient3d-adversarial");
  std::string input;
  std::vector<Sign> expected;
  for (int i = 0; i < 3000; ++i) {
    std::array<Point3, 4> p;
    const int scale = testing::uniform_int(rng, -1060, 1000);
    for (int k = 0; k < 3; ++k)
      p[k] = testing::scaled(testing::integer_point(rng, 1 << 8), scale);
    // exactly coplanar, then possibly one ulp off, at every scale; or mixed magnitudes
    p[3] = testing::rounded_affine(p[0], p[1], p[2], testing::uniform_int(rng, -2, 2),
                                   testing::uniform_int(rng, -2, 2));
    if (i % 3 == 1) p[3] = testing::ulp_step(p[3], i % 3, i % 2 ? 1 : -1);
    if (i % 3 == 2) p[2] = testing::random_magnitude_point(rng, -1074, 1000);
    input += hexfloat_line(p);
    expected.push_back(testing::orient3d_oracle(p[0], p[1], p[2], p[3]));
  }
  const Outcome r = run(PredicateKind::orient3d, input);
  ASSERT_EQ(r.code, ExitCode::success) << r.err;
  std::istringstream lines(r.out);
  for (const Sign s : expected) {
    int answer = 99;
    lines >> answer;
    ASSERT_EQ(answer, to_int(s));
  }
}

/// Randomised robustness: arbitrary bytes and mutations of valid lines never crash
/// (this also runs under AddressSanitizer/UBSan in CI), and either succeed with one answer
/// per case or fail with exit code 2, a one-line message and nothing on stdout.
TEST(PredicateCommand, ArbitraryInputNeverCrashesOrLeaksPartialOutput) {
  testing::Rng rng = testing::seeded_engine("cli-fuzz");
  const std::string alphabet = "0123456789+-.eExXpP ,#\t\r\nabcdfinINaA\x01\xff";
  const std::string valid = "0.5 -1e3 0x1.8p2 7 8 9 1,2,3 0 0 1\n";
  for (int i = 0; i < 20000; ++i) {
    std::string input;
    if (i % 2 == 0) {
      const int n = testing::uniform_int(rng, 0, 80);
      for (int k = 0; k < n; ++k)
        input += alphabet[testing::uniform_int(rng, 0, int(alphabet.size()) - 1)];
    } else {
      input = valid + valid;
      const int edits = testing::uniform_int(rng, 1, 4);
      for (int k = 0; k < edits; ++k) {
        const auto at = std::size_t(testing::uniform_int(rng, 0, int(input.size()) - 1));
        input[at] = alphabet[testing::uniform_int(rng, 0, int(alphabet.size()) - 1)];
      }
    }
    for (const PredicateKind kind : {PredicateKind::orient3d, PredicateKind::ray_patch}) {
      const Outcome r = run(kind, input);
      if (r.code == ExitCode::success) {
        EXPECT_EQ(r.err, "");
      } else {
        ASSERT_EQ(r.code, ExitCode::input_error);
        EXPECT_EQ(r.out, "");
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      }
    }
  }
}

}  // namespace
}  // namespace exactgeo::cli
