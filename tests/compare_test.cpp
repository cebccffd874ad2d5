// The comparison reports the worst element as where / expected / observed.
#include <catch2/catch.hpp>

#include <limits>

#include "check/compare.h"

TEST_CASE("compare finds the worst element and says where, expected and observed") {
  pn::Image expected(4, 3), observed(4, 3);
  observed.at(1, 1) = 1e-6f;
  observed.at(2, 2) = -0.5f;
  const auto tol = pn::Tolerance::absolute(1e-3);
  const pn::Comparison c = pn::compare(expected, observed, tol);
  CHECK_FALSE(c.pass);
  CHECK(c.x == 2);
  CHECK(c.y == 2);
  CHECK(c.worst_error == 0.5);
  CHECK(c.where(tol) == "at (2, 2): expected 0, observed -0.5 (abs error 5.00e-01, not within abs <= 1.00e-03)");
}

TEST_CASE("exact tolerance passes only identical values; NaN equals NaN, not a number") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pn::Image a(2, 1), b(2, 1);
  a.at(0, 0) = b.at(0, 0) = nan;
  CHECK(pn::compare(a, b, pn::Tolerance::exact()).pass);
  b.at(1, 0) = std::nextafter(0.0f, 1.0f);
  CHECK_FALSE(pn::compare(a, b, pn::Tolerance::exact()).pass);
  b.at(1, 0) = 0.0f;
  b.at(0, 0) = 1.0f;
  const pn::Comparison c = pn::compare(a, b, pn::Tolerance::absolute(1e9));
  CHECK_FALSE(c.pass);
  CHECK(std::isinf(c.worst_error));
}

TEST_CASE("relative and RMSE tolerances measure what they say") {
  pn::Image e(2, 1), o(2, 1);
  e.at(0, 0) = 100.0f, o.at(0, 0) = 101.0f;  // rel 1e-2
  e.at(1, 0) = 1.0f, o.at(1, 0) = 1.0f;
  CHECK(pn::compare(e, o, pn::Tolerance::relative(0.011)).pass);
  CHECK_FALSE(pn::compare(e, o, pn::Tolerance::relative(0.009)).pass);
  const pn::Comparison r = pn::compare(e, o, pn::Tolerance::rmse(1.0));
  CHECK(r.rmse == Approx(std::sqrt(0.5)));
  CHECK(r.pass);
}

TEST_CASE("negative: images of different sizes do not compare") {
  const pn::Comparison c = pn::compare(pn::Image(2, 2), pn::Image(2, 3), pn::Tolerance::absolute(1.0));
  CHECK_FALSE(c.pass);
  CHECK(c.problem == "size mismatch: expected 2x2x1, observed 2x3x1");
}
