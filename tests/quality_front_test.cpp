// The front picker on a small hand-made front: cheapest meeting the target, none
// meeting it (the most accurate), ties, and the CSV round trip.
#include "shading/quality_front.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace skylit::shading {
namespace {

FrontPoint point(Product p, int w, double cost, double error) {
  FrontPoint f;
  f.product = p;
  f.settings = quality_settings(Quality::Default);
  f.settings.azimuths = w;
  f.relative_cost = cost;
  f.error = error;
  f.label = "W" + std::to_string(w);
  return f;
}

const std::vector<FrontPoint> kFront = {
    point(Product::Svf, 8, 0.3, 0.02),    point(Product::Svf, 16, 0.5, 0.01), point(Product::Svf, 32, 1.0, 0.005),
    point(Product::Svf, 64, 2.0, 0.005),  point(Product::Svf, 24, 0.5, 0.008),  // ties W16 on cost, lower error
    point(Product::Shaded, 16, 0.5, 2.0), point(Product::Shaded, 32, 1.0, 1.0)};

TEST(QualityFront, CheapestMeetingTheTarget) {
  EXPECT_EQ(pick_setting(kFront, Product::Svf, 0.05).point.settings.azimuths, 8);
  EXPECT_EQ(pick_setting(kFront, Product::Svf, 0.02).point.settings.azimuths, 8);  // ≤ E, not < E
  EXPECT_EQ(pick_setting(kFront, Product::Svf, 0.006).point.settings.azimuths, 32);
  EXPECT_TRUE(pick_setting(kFront, Product::Svf, 0.006).met);
  EXPECT_EQ(pick_setting(kFront, Product::Shaded, 1.5).point.settings.azimuths, 32);
}

TEST(QualityFront, TiesOnCostGoToTheLowerError) {
  EXPECT_EQ(pick_setting(kFront, Product::Svf, 0.015).point.settings.azimuths, 24);
}

TEST(QualityFront, NoneMeetsTakesTheMostAccurateAndTheCheaperOfEqualErrors) {
  const FrontChoice c = pick_setting(kFront, Product::Svf, 0.001);
  EXPECT_FALSE(c.met);
  EXPECT_EQ(c.point.settings.azimuths, 32);  // 0.005 at cost 1, not W64 at cost 2
}

TEST(QualityFront, BadTargetOrMissingProductThrows) {
  EXPECT_THROW(pick_setting(kFront, Product::Svf, 0), std::invalid_argument);
  EXPECT_THROW(pick_setting(kFront, Product::Svf, -1), std::invalid_argument);
  EXPECT_THROW(pick_setting(kFront, Product::Skyview, 0.1), std::invalid_argument);
}

TEST(QualityFront, CsvRoundTripAndBadLines) {
  std::string text = "# comment\n" + std::string(front_csv_header()) + "\n";
  for (const auto& p : kFront) text += front_csv_line(p) + "\n";
  const auto back = parse_front(text);
  ASSERT_EQ(back.size(), kFront.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].product, kFront[i].product);
    EXPECT_EQ(back[i].settings.azimuths, kFront[i].settings.azimuths);
    EXPECT_EQ(back[i].settings.horizons, kFront[i].settings.horizons);
    EXPECT_DOUBLE_EQ(back[i].error, kFront[i].error);
    EXPECT_EQ(back[i].label, kFront[i].label);
  }
  EXPECT_THROW(parse_front("nonsense\n"), std::runtime_error);
  EXPECT_THROW(parse_front(std::string(front_csv_header()) + "\nsvf,march,8\n"), std::runtime_error);
}

TEST(QualityFront, ShippedFrontLoadsWithAllThreeProducts) {
  const auto front = load_front(std::string(SKYLIT_SOURCE_DIR) + "/data/quality/front.csv");
  for (Product p : {Product::Svf, Product::Skyview, Product::Shaded})
    EXPECT_NO_THROW(pick_setting(front, p, 1.0)) << product_name(p);
}

}  // namespace
}  // namespace skylit::shading
