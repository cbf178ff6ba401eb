// The editor's number fields' ranges (editor/edit/number_field.h): every field has one,
// and a value outside it is refused in words, with the field's name and unit.
#include "editor/edit/number_field.h"

#include <cmath>
#include <limits>
#include <set>

#include <gtest/gtest.h>

namespace pw::edit {
namespace {

TEST(FieldRanges, EveryFieldHasARangeAndAUnit) {
  std::set<std::string_view> labels;
  for (const FieldRange& range : kFieldRanges) {
    EXPECT_TRUE(labels.insert(range.label).second) << range.label;
    EXPECT_FALSE(range.name.empty()) << range.label;
    EXPECT_FALSE(range.unit.empty()) << range.label;
    EXPECT_LT(range.min, range.max) << range.label;
    EXPECT_EQ(fieldRange(range.label), &range);
  }
  EXPECT_EQ(fieldRange("no such field"), nullptr);
}

TEST(FieldRanges, AValueOutsideIsRefusedInWords) {
  const FieldRange& focal = *fieldRange("focal px");
  EXPECT_EQ(refusal(focal, 700773020), "focal length 700773020 px: expected 50-50000 px");
  EXPECT_EQ(refusal(focal, 49.5), "focal length 49.5 px: expected 50-50000 px");
  EXPECT_EQ(refusal(focal, 803.68), std::nullopt);
  EXPECT_EQ(refusal(focal, 50), std::nullopt);  // the bounds are in range
  EXPECT_EQ(refusal(focal, 50000), std::nullopt);
  EXPECT_EQ(refusal(focal, std::numeric_limits<double>::infinity()), "focal length inf px: expected 50-50000 px");
  EXPECT_TRUE(refusal(focal, std::nan("")).has_value());
  const FieldRange& height = *fieldRange("camera height m");
  EXPECT_EQ(refusal(height, 1.5), std::nullopt);
  EXPECT_EQ(refusal(height, 700650), "camera height 700650 m: expected 0.05-100 m");
  EXPECT_EQ(refusal(height, 0), "camera height 0 m: expected 0.05-100 m");
  EXPECT_EQ(refusal(height, -1.6), "camera height -1.6 m: expected 0.05-100 m");
}

TEST(FieldRanges, ThePrincipalPointsRangeIsThePhotoWidenedByItsSize) {
  const FieldRange& u = *fieldRange("principal u px");
  EXPECT_EQ(refusal(u, 511.5, 1024), std::nullopt);
  EXPECT_EQ(refusal(u, -1000, 1024), std::nullopt);  // a photo cropped to one side
  EXPECT_EQ(refusal(u, 5000, 1024), "principal point u 5000 px: expected -1024 to 2048 px");
}

}  // namespace
}  // namespace pw::edit
