// setDefaultFade (see edit_defaults.h).
#include "shows/edit/edit_defaults.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "shows/edit/edit_util.h"

namespace haze {

namespace {

using edit::userError;

class SetDefaultFade final : public EditCommand {
 public:
  explicit SetDefaultFade(double s) : after_(s) {}
  std::string label() const override {
    std::ostringstream o;
    o << "Default fade " << after_ << " s";
    return o.str();
  }
  Status apply(EditTarget& t) override {
    if (!std::isfinite(after_) || after_ < 0.0 || after_ > kMaxDefaultFadeS)
      return userError("default fade", "a default fade is 0..3600 seconds");
    before_ = std::exchange(t.show.defaultFadeS, after_);
    return Ok{};
  }
  void undo(EditTarget& t) override { t.show.defaultFadeS = before_; }

 private:
  double after_, before_ = 0.0;
};

}  // namespace

std::unique_ptr<EditCommand> setDefaultFade(double seconds) { return std::make_unique<SetDefaultFade>(seconds); }

}  // namespace haze
