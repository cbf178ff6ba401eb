// The editor's number fields (the Camera panel, building mode's placement): each has a
// range and a unit, from one table (kFieldRanges); a value outside it is refused at the
// field, in words ("focal length 700773020 px: expected 50-50000 px"), and the value
// committed stays. A field commits on Enter, Tab or losing the focus (a click
// elsewhere), and always starts editing from its committed value.
//
//   NumberFields fields_;   // one per panel: the field being typed into
//   double v;
//   if (fields_.field(shell, "focal px", shot.focalPx, &v, "%.1f")) after.focalPx = v;
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pw::app {
class Shell;
}

namespace pw::edit {

struct FieldRange {
  std::string_view label;  // the field's ImGui label (its id), as the trace's widgets name it
  std::string_view name;   // in words, for messages
  double min, max;         // in `unit`; times the photo's side where `perPhotoSide`
  std::string_view unit;
  bool perPhotoSide = false;  // the principal point: within the photo's width (height) around it
};

// Every number field the editor has (README "The editor": the table of field ranges).
inline constexpr std::array<FieldRange, 15> kFieldRanges{{
    {"focal px", "focal length", 50, 50000, "px"},
    {"focal mm", "focal length", 0.5, 2000, "mm"},
    {"sensor width mm", "sensor width", 1, 100, "mm"},
    {"principal u px", "principal point u", -1, 2, "px", true},
    {"principal v px", "principal point v", -1, 2, "px", true},
    {"distortion k1", "distortion k1", -2, 2, "per (r/f)^2"},
    {"distortion k2", "distortion k2", -2, 2, "per (r/f)^4"},
    {"corner u px", "corner u", -1, 2, "px", true},
    {"corner v px", "corner v", -1, 2, "px", true},
    {"camera height m", "camera height", 0.05, 100, "m"},
    {"reference m", "reference length", 0.01, 10000, "m"},
    {"offset m", "offset", -10000, 10000, "m"},
    {"x m", "x", -100000, 100000, "m"},
    {"z m", "z", -100000, 100000, "m"},
    {"rotation deg", "rotation", -360, 360, "deg"},
}};

// The row of the field labelled `label`, or nullptr.
const FieldRange* fieldRange(std::string_view label);

// A number as a person would write it: 1.5, 700773020, 0.001, -1024, 1e+20, nan.
std::string numberInWords(double value);

// Why `value` is refused for the field (outside [min, max] x `photoSide` where the range
// is per photo side, or not finite): "focal length 700773020 px: expected 50-50000 px";
// nullopt when it is in range.
std::optional<std::string> refusal(const FieldRange& range, double value, double photoSide = 1);

// The state of the field being typed into (one per panel) and the last refusal.
class NumberFields {
 public:
  // Draws the field `label` (a row of kFieldRanges) showing `committed`. True, with
  // `*edited` set, when an edit that changes the value is committed within range. A
  // value out of range is refused: false, and the refusal goes to Shell::showMessage
  // and to drawRefusal until the field is edited again. `photoSide`: the photo's
  // width (u) or height (v) for a per-side range.
  bool field(app::Shell& shell, const char* label, double committed, double* edited, const char* format,
             double photoSide = 1);

  // The refusal of the field `label`, if it is the last one, in the panel's error colour
  // (call it after the field, and after reading the field's rectangle).
  void drawRefusal(const char* label) const;

  // The last refusal, while it is shown (the trace's "refused").
  const std::optional<std::string>& refused() const { return refused_; }

 private:
  // The fields typed into (ImGuiID), the ImGui frame each was last active in and its
  // value so far: one, or two in the frame a click moves from one to another.
  struct Typed {
    unsigned id;
    int frame;
    double value;
  };
  std::vector<Typed> typed_;
  unsigned refusedId_ = 0;
  std::optional<std::string> refused_;
};

}  // namespace pw::edit
