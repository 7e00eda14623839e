// Exposure like a camera's (docs/rendering.md, "Exposure"): the meter that picks an EV from the
// rendered radiance, and the smoothing that lets a window's exposure follow it without flicker.
// GL-free so it can be tested on known images; the renderer feeds it a downsampled luminance.
#pragma once

#include <span>

#include <glm/vec3.hpp>

namespace haze {

// The manual key: at EV 0 a surface of 50 cd/m^2 (a lit stage deck) maps to 1 before the curve.
constexpr float kManualKeyNits = 50.0f;

enum class ExposureMode { Auto, Manual };

// What the user asks for: in Auto, ev is an offset from the metered EV; in Manual it is absolute
// (DisplaySettings::exposureEv: EV 0 maps 50 cd/m^2 to 1 before the tone curve).
struct ExposureChoice {
  ExposureMode mode = ExposureMode::Auto;
  float ev = 0.0f;
};

struct MeterSettings {
  // The highlight that sets the exposure: a stage is mostly dark, so an average would push the
  // lit deck and the beams into white. The 99th percentile of the (block-averaged) luminance
  // lands at kHighlightDisplay, just below the ACES shoulder's clip (display 3.1 = sRGB 250).
  float percentile = 0.99f;
  float highlightDisplay = 2.0f;
  // A scene without a dark surround (a wash on a bright cyc) is keyed like a photograph instead:
  // its log-average at 0.18, whichever of the two is darker.
  float averageKey = 0.18f;
  // A blackout would be metered up into noise and ambient grey; a camera runs out of gain too.
  float minEv = -16.0f;
  float maxEv = 4.0f;
};

struct Metering {
  float ev = 0.0f;              // the absolute EV the meter chose (same meaning as Manual)
  float highlightNits = 0.0f;   // the percentile's luminance, cd/m^2
  float logAverageNits = 0.0f;  // exp(mean(log L)), cd/m^2
};

// Rec. 709 luminance of linear RGB radiance.
float luminanceOf(glm::vec3 rgb);

// Meters luminances in cd/m^2 (negative and non-finite ones are ignored; none at all gives maxEv).
Metering meterLuminance(std::span<const float> nits, const MeterSettings& settings = {});

// The absolute EV for a choice, given what the meter says.
float exposureEvFor(const ExposureChoice& choice, float meteredEv);

// One step of exponential smoothing in EV with time constant tauS: a fade does not flicker and a
// cut settles in about three tau. A non-finite current EV (the first frame) jumps to the target.
float adaptEv(float currentEv, float targetEv, float dtS, float tauS = 0.3f);

}  // namespace haze
