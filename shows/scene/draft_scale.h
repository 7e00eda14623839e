// The share of the viewport's pixels that a draft frame is drawn at while the view or the stage
// moves. A frame's cost is mostly per pixel (the lit surfaces and the walks through the beams),
// so a rig too heavy for the window's full size is drawn smaller and stretched, as a 3D view
// drops its resolution while orbiting, and the full size comes back when the view is still.
#pragma once

namespace haze {

class DraftScale {
 public:
  // budgetMs: the frame time to keep (0: always the full size). minScale: the smallest linear
  // scale (a quarter of the width keeps a beam's shape readable).
  explicit DraftScale(double budgetMs = 0.0, float minScale = 0.25f);

  // After a draft frame drawn at scale() took frameMs (the whole frame, from one to the next):
  // the scale for the next draft frame.
  float update(double frameMs);
  float scale() const { return scale_; }
  double budgetMs() const { return budgetMs_; }
  // A new budget; the scale starts again from the full size.
  void setBudget(double budgetMs);
  // Whether the last update wanted a smaller scale than the minimum: the budget is not met.
  bool limited() const { return limited_; }

 private:
  double budgetMs_;
  float minScale_;
  float scale_ = 1.0f;
  bool limited_ = false;
};

}  // namespace haze
