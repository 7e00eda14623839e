// The GUI's window and frame loop: a window on one show, drawn by the same renderer as
// `haze render` into the viewport between the panels (app/gui/gui.h lists them). Draft quality
// while anything moves (a drag, a fade, an edit), the chosen quality when still, refining
// progressively. `haze open SHOW --screenshot OUT.png --frames N` draws N frames of the whole
// window (panels included), writes it and exits.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands.h"
#include "shows/frame/frame_builder.h"
#include "app/command_line.h"
#include "app/gui/gui.h"
#include "shows/hazer_levels.h"
#include "shows/edit/recent_files.h"
#include "app/render_session.h"
#include "shows/frame/live_session.h"
#include "app/gui/window_context.h"
#include "renderer/gl/gl.h"
#include "renderer/renderer.h"
#include "shows/scene/draft_scale.h"
#include "shows/scene/image.h"

namespace haze {
namespace {

struct Options {
  std::string show;
  std::string screenshot;
  int frames = 0;
  int width = 1280, height = 720;
  std::string cue;  // start with this cue on stage in full ("" = the first cue)
  std::optional<Quality> quality;
  std::vector<int> select;
  bool help = false;
  std::string tab;  // the show panel's tab to show first
  bool artNet = false, sacn = false;  // live DMX input from a console drives the fixtures
  std::string bind = "127.0.0.1";
  std::optional<ExposureMode> exposureMode;
  std::optional<float> exposureEv;
  double turntableDeg = 0.0;  // the view turns this much about its target every frame
  int turnFirst = 0, turnLast = -1;  // --turn-frames A-B: only frames A..B turn; -1: every frame
  double draftBudgetMs = -1.0;  // < 0: the GUI's own
};

constexpr const char* kUsage =
    "haze open SHOW [--width W --height H] [--cue N] [--select ID]... [--tab cues|fixtures|library|patch|air|playback]\n"
    "               [--quality draft|default|high] [--help-window] [--sacn] [--artnet] [--bind ADDR]\n"
    "               [--exposure EV] [--exposure-mode auto|manual] [--draft-budget MS]\n"
    "               [--turntable DEG [--turn-frames A-B]] [--screenshot OUT.png] [--frames N]\n"
    "The designer's GUI on a show (the bundled demo when none is given); docs/gui.md.\n"
    "--draft-budget: while anything moves, frames are drawn smaller to take about MS (default 50,\n"
    "0: always the full size). --turntable: the view turns DEG degrees a frame (a demo, a test);\n"
    "--turn-frames A-B: during frames A to B only (counted from 0), so that the summary says how long\n"
    "the first frame at the chosen quality took to show after the view stopped.\n"
    "--frames N draws N frames and exits; with --screenshot, of the whole window, written at the end.\n";

int fail(const std::string& line) {
  std::fprintf(stderr, "haze: %s\n", line.c_str());
  return 1;
}

Status saveScreenshot(int width, int height, const std::string& file) {
  std::vector<unsigned char> rgba(static_cast<size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  std::vector<unsigned char> rgb(static_cast<size_t>(width) * height * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[(static_cast<size_t>(y) * width + x) * 3 + c] = rgba[(static_cast<size_t>(height - 1 - y) * width + x) * 4 + c];
  return writePng8(rgb, width, height, file);
}

// Parses `haze open` options; nullopt: go on, else the exit status (usage printed or an error).
std::optional<int> parseOptions(const Args& args, Options& opt) {
  std::string quality, exposureMode;
  double exposure = std::nan("");
  CommandLine cli("haze open", kUsage);
  cli.text("--screenshot", opt.screenshot, "a file name")
      .flag("--artnet", opt.artNet)
      .flag("--sacn", opt.sacn)
      .flag("--help-window", opt.help)
      .text("--bind", opt.bind, "an address")
      .text("--tab", opt.tab, "cues, fixtures, library, patch, air or playback")
      .text("--cue", opt.cue, "a cue number")
      .integer("--frames", opt.frames, 1, 1000000, "a positive number")
      .integer("--width", opt.width, 1, 16384, "a positive number")
      .integer("--height", opt.height, 1, 16384, "a positive number")
      .custom("--select", "a fixture id",
              [&opt](const std::string& v) {
                int id = 0;
                const auto r = std::from_chars(v.data(), v.data() + v.size(), id);
                if (r.ec != std::errc() || r.ptr != v.data() + v.size() || id <= 0) return false;
                opt.select.push_back(id);
                return true;
              })
      .choice("--quality", quality, {"draft", "default", "high"})
      .number("--exposure", exposure, -100, 100, "a number of EV")
      .number("--turntable", opt.turntableDeg, -180, 180, "degrees per frame")
      .custom("--turn-frames", "frames A-B (0 <= A <= B)",
              [&opt](const std::string& v) {
                const size_t dash = v.find('-');
                if (dash == std::string::npos) return false;
                int a = 0, b = 0;
                const auto ra = std::from_chars(v.data(), v.data() + dash, a);
                const auto rb = std::from_chars(v.data() + dash + 1, v.data() + v.size(), b);
                if (ra.ec != std::errc() || ra.ptr != v.data() + dash || rb.ec != std::errc() ||
                    rb.ptr != v.data() + v.size() || a < 0 || b < a)
                  return false;
                opt.turnFirst = a;
                opt.turnLast = b;
                return true;
              })
      .number("--draft-budget", opt.draftBudgetMs, 0, 10000, "milliseconds (0 or more)")
      .choice("--exposure-mode", exposureMode, {"auto", "manual"})
      .positional(opt.show, "show", false);
  if (auto done = cli.parse(args)) return done;
  if (!quality.empty()) opt.quality = *parseQuality(quality);
  opt.exposureMode = parseExposureMode(exposureMode);
  if (!std::isnan(exposure)) opt.exposureEv = static_cast<float>(exposure);
  if (opt.show.empty()) opt.show = HAZE_DEMO_SHOW;
  if (!opt.screenshot.empty() && opt.frames <= 0) opt.frames = 3;
  return std::nullopt;
}

// The command line's choices that need the open show: cue, selection, tab, live input.
Status applyOptions(Gui& gui, const Options& opt) {
  if (!opt.cue.empty()) {
    const CueList* list = gui.doc->cueList();
    auto at = list ? findCue(*list, opt.cue) : Result<size_t>(Error{"", "--cue", "the show has no cue list"});
    if (!at) return at.error();
    gui.doc->jumpTo(*at, 0.0);
    gui.cueCursor = *at;
  }
  for (int id : opt.select) {
    if (!gui.doc->show().findFixture(id)) return Error{"", "--select", "the show has no fixture " + std::to_string(id)};
    applyClickToSelection(gui.doc->selection, id, false, true);
  }
  if (opt.quality) gui.quality = *opt.quality;
  if (opt.draftBudgetMs >= 0.0) gui.draftBudgetMs = opt.draftBudgetMs;
  // The show's first camera may carry an exposure; the command line wins, as in haze render.
  const ExposureChoice exposure = exposureChoiceFor(
      gui.doc->show(), {.exposureMode = opt.exposureMode, .exposureEv = opt.exposureEv});
  gui.exposureMode = exposure.mode;
  gui.exposureEv = exposure.ev;
  gui.showHelp = opt.help;
  if (!opt.tab.empty()) {
    for (const std::string_view n : kShowTabs)
      if (std::equal(n.begin(), n.end(), opt.tab.begin(), opt.tab.end(),
                     [](char a, char b) { return std::tolower(a) == std::tolower(b); }))
        gui.openTab = n;
    if (gui.openTab.empty()) return Error{"", "--tab", "expected cues, fixtures, library, patch, air or playback, not '" + opt.tab + "'"};
  }
  gui.recent = loadRecentFiles(recentFilesPath());
  loadViewSettings(gui, opt.quality.has_value(), opt.exposureMode.has_value());
  if (opt.artNet || opt.sacn) {
    // The same session as `haze live`, DMX only; the GUI follows the heads itself (cues and
    // DMX alike), and says nothing on stderr.
    LiveInputs in;
    in.dmx.udp.bindAddress = opt.bind;
    in.dmx.udp.artNet = opt.artNet;
    in.dmx.udp.sacn = opt.sacn;
    auto session = std::make_unique<LiveSession>(gui.doc->show(), gui.doc->profiles(),
                                                 LiveSessionConfig{.followHeads = false}, nullptr);
    if (Status s = session->listen(in); !s) return s.error();
    gui.live = std::move(session);
    gui.liveBind = opt.bind;
  }
  return Ok{};
}

void initImGui(Gui& gui) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is ours, not a file in the working folder
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0.0f;
  // Installed before ImGui's callbacks, which call it after their own.
  glfwSetWindowUserPointer(gui.window, &gui);
  glfwSetKeyCallback(gui.window, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_PRESS) static_cast<Gui*>(glfwGetWindowUserPointer(w))->keys.push_back({key, mods});
  });
  ImGui_ImplGlfw_InitForOpenGL(gui.window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

// The stage as the heads really are: cue fades are sampled once a frame (the command moves
// linearly between frames), live DMX values are steps.
void followHeads(Gui& gui) {
  if (!gui.realMovement) {
    gui.heads.reset();
    return;
  }
  if (!gui.heads || gui.headsDoc != gui.doc.get()) {
    gui.heads = std::make_unique<MovementFollower>(gui.doc->show(), gui.doc->profiles());
    gui.heads->reset(gui.stage, gui.nowS);
    gui.headsDoc = gui.doc.get();
  }
  // Live, the heads start where the first DMX puts them (as `haze live`), once per receiver.
  static const LiveSession* seededFor = nullptr;
  if (gui.live && gui.live.get() != seededFor && gui.live->dmxArrived()) {
    gui.heads->reset(gui.stage, gui.nowS);
    seededFor = gui.live.get();
  }
  gui.stage = gui.heads->advance(gui.stage, gui.nowS, !gui.live);
}

// With HAZE_GUI_FRAME_FILE set, the number of frames presented so far, rewritten (atomically)
// after every swap: the GUI tests wait on it for their input to be handled and drawn instead of
// sleeping for a guessed time, which fails when a loaded machine makes frames slow.
void publishFrameCount(int frame) {
  static const char* path = std::getenv("HAZE_GUI_FRAME_FILE");
  if (!path || !*path) return;
  const std::string tmp = std::string(path) + ".tmp";
  if (std::FILE* f = std::fopen(tmp.c_str(), "w")) {
    std::fprintf(f, "%d\n", frame);
    if (std::fclose(f) == 0) std::rename(tmp.c_str(), path);
  }
}

bool probing() {
  static const char* path = std::getenv("HAZE_GUI_PROBE_FILE");
  return path && *path;
}

// The mean of R, G and B (0..1, as displayed) over a framebuffer rectangle just drawn.
float meanLevel(int x, int y, int w, int h) {
  std::vector<unsigned char> rgba(static_cast<size_t>(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  double sum = 0.0;
  for (size_t i = 0; i < rgba.size(); i += 4) sum += rgba[i] + rgba[i + 1] + rgba[i + 2];
  return static_cast<float>(sum / (3.0 * 255.0 * static_cast<double>(w) * h));
}

// With HAZE_GUI_PROBE_FILE set, what the last frame drew that a screenshot cannot tell a test
// exactly, as one JSON object rewritten (atomically) after every frame, before the frame count:
// whether View > Fixture numbers is on, the rows the Fixtures and Patch tabs listed (ids, in order; only the visible tab's are
// current), the filter field's rectangle, and the selected fixtures' label boxes in the viewport
// (window pixels) with their markers and whether each was pushed off its place (tests/gui/fixture_identity.sh);
// the exposure (locked or not, the EV shown and metered) with the viewport's mean level and the
// GUI's clock (tests/gui/exposure_lock.sh), each fixture's intensity on stage, and the show
// panel's width and its tabs' widths drawn and needed (tests/gui/panel_tabs.sh), and the status
// line (tests/gui/view_settings.sh), and the beams of the frame (tests/gui/view_cells.sh).
void publishProbe(const Gui& gui) {
  if (!probing()) return;
  const char* path = std::getenv("HAZE_GUI_PROBE_FILE");
  const auto ids = [](const std::vector<int>& v) {
    std::string out;
    for (int id : v) out += (out.empty() ? "" : ",") + std::to_string(id);
    return "[" + out + "]";
  };
  std::string labels;
  for (const PlacedLabel& l : gui.placedLabels) {
    char one[200];
    std::snprintf(one, sizeof one,
                  "%s{\"fixture\":%d,\"anchor\":[%.1f,%.1f],\"x\":%.1f,\"y\":%.1f,\"w\":%.1f,\"h\":%.1f,\"moved\":%s}",
                  labels.empty() ? "" : ",", l.fixture, l.anchor.x, l.anchor.y, l.box.x, l.box.y, l.box.w, l.box.h,
                  l.moved ? "true" : "false");
    labels += one;
  }
  char exposure[200];
  std::snprintf(exposure, sizeof exposure, ",\"clock_s\":%.4f,\"exposure\":{\"locked\":%s,\"ev\":%.4f,\"metered_ev\":%.4f},\"view_mean\":%.6f",
                gui.nowS, gui.exposureLocked() ? "true" : "false", std::isfinite(gui.shownEv) ? gui.shownEv : 0.0f,
                gui.meteredEv, std::isfinite(gui.viewMean) ? gui.viewMean : -1.0f);
  // Each fixture's intensity on stage this frame (tests/gui/command_words.sh times a fade by it).
  std::string stage;
  for (const auto& [id, a] : gui.stage) {
    char one[48];
    std::snprintf(one, sizeof one, "%s\"%d\":%.5f", stage.empty() ? "" : ",", id, a.intensity);
    stage += one;
  }
  char panel[64];
  std::snprintf(panel, sizeof panel, "\"show_panel_w\":%.1f", gui.layout.left.w);
  std::string tabs;
  for (const Gui::TabShown& t : gui.tabsShown) {
    char one[120];
    std::snprintf(one, sizeof one, "%s{\"name\":\"%s\",\"width\":%.1f,\"needed\":%.1f}", tabs.empty() ? "" : ",",
                  t.name.c_str(), t.widthPx, t.neededPx);
    tabs += one;
  }
  char filter[160];
  const Rect& r = gui.filterField;
  std::snprintf(filter, sizeof filter, "{\"x\":%.1f,\"y\":%.1f,\"w\":%.1f,\"h\":%.1f}", r.x, r.y, r.w, r.h);
  const Gui::LibraryProbe& lp = gui.libraryProbe;
  auto rectJson = [](const Rect& q) {
    char one[128];
    std::snprintf(one, sizeof one, "{\"x\":%.1f,\"y\":%.1f,\"w\":%.1f,\"h\":%.1f}", q.x, q.y, q.w, q.h);
    return std::string(one);
  };
  const std::string library = "{\"search\":" + rectJson(lp.search) + ",\"first_hit\":" + rectJson(lp.firstHit) +
                              ",\"change\":" + rectJson(lp.change) + ",\"hits\":" + std::to_string(lp.hits) + "}";
  // The status line, as a JSON string (tests/gui/view_settings.sh reads a warning on it).
  std::string status;
  for (const char c : gui.status) {
    if (c == '"' || c == '\\') status += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) status += c;
  }
  const std::string text = "{\"numbers\":" + std::string(gui.showNumbers ? "true" : "false") +
                           ",\"fixture_rows\":" + ids(gui.fixtureRows) + ",\"patch_rows\":" + ids(gui.patchRows) +
                           ",\"filter_field\":" + filter + ",\"library\":" + library + ",\"labels\":[" + labels + "]" + exposure +
                           ",\"intensity\":{" + stage + "},\"tabs\":[" + tabs + "]," + panel +
                           ",\"status\":\"" + status + "\",\"status_error\":" + (gui.statusError ? "true" : "false") +
                           ",\"beams\":" + std::to_string(gui.beamsDrawn) + "}\n";
  const std::string tmp = std::string(path) + ".tmp";
  if (std::FILE* f = std::fopen(tmp.c_str(), "w")) {
    std::fputs(text.c_str(), f);
    if (std::fclose(f) == 0) std::rename(tmp.c_str(), path);
  }
}

// Every panel of one frame, from input to ImGui's draw lists.
void drawPanels(Gui& gui, int winW, int winH) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (!ImGui::IsAnyItemActive()) gui.mergeItem = 0;  // the next widget edit starts a new undo step
  gui.layout = layoutFor(static_cast<float>(winW), static_cast<float>(winH), ImGui::GetFrameHeight(),
                         showPanelWidth(gui, static_cast<float>(winW)));
  gui.stage = gui.live ? gui.live->pass(0) : gui.doc->stageState(gui.nowS);
  followHeads(gui);

  handleShortcuts(gui);
  drawMenuBar(gui);
  drawShowPanel(gui);
  drawCommandLine(gui);
  drawInspector(gui);
  drawHelp(gui);
  drawImportWarnings(gui);
  drawXchangeWindow(gui);
  drawFileDialogs(gui);
  handleViewport(gui);
  keepViewSettings(gui);
  ImGui::Render();
}

// Milliseconds of shadow-map and light-map work per frame (at least one map a frame).
constexpr double kMapBudgetMs = 15.0;

// Two renderers: draft while anything moves, the chosen quality when still.
struct ViewportRenderers {
  std::unique_ptr<Renderer> draft, still;
  int width = 0, height = 0;
  int draftWidth = 0, draftHeight = 0;  // the draft's share of the viewport (DraftScale)
  DraftScale draftScale;
  Quality quality = Quality::Default;
  const ShowDocument* doc = nullptr;

  Status fit(Gui& gui, int vw, int vh) {
    if (draftScale.budgetMs() != gui.draftBudgetMs) draftScale.setBudget(gui.draftBudgetMs);
    const int dw = std::max(1, static_cast<int>(std::lround(vw * draftScale.scale())));
    const int dh = std::max(1, static_cast<int>(std::lround(vh * draftScale.scale())));
    const bool sameRenderers = still && gui.quality == quality && doc == gui.doc.get();
    if (sameRenderers && vw == width && vh == height) {
      if (dw == draftWidth && dh == draftHeight) return Ok{};
      // A new draft scale remakes the draft's targets; its maps and programs are kept.
      if (Status d = draft->resize(dw, dh); !d) return d;
      draftWidth = dw;
      draftHeight = dh;
      return Ok{};
    }
    if (sameRenderers) {
      // A resized viewport remakes only the renderers' targets; their programs are kept.
      if (Status d = draft->resize(dw, dh); !d) return d;
      if (Status s = still->resize(vw, vh); !s) return s;
      width = vw;
      height = vh;
      draftWidth = dw;
      draftHeight = dh;
      gui.stillFrames = 0;
      return Ok{};
    }
    // A new document may have a new venue: the renderers are made for one venue.
    // Maps of moving beams are redrawn a few per frame (RenderSettings::mapWorkBudgetMs): 76
    // heads in a fade would otherwise redraw 76 shadow maps in every frame.
    RenderSettings draftSettings = renderSettingsFor(Quality::Draft, dw, dh);
    RenderSettings stillSettings = renderSettingsFor(gui.quality, vw, vh);
    draftSettings.mapWorkBudgetMs = stillSettings.mapWorkBudgetMs = kMapBudgetMs;
    auto d = Renderer::create(gui.doc->venue(), draftSettings);
    if (!d) return d.error();
    auto s = Renderer::create(gui.doc->venue(), stillSettings);
    if (!s) return s.error();
    draft = std::move(*d);
    still = std::move(*s);
    width = vw;
    height = vh;
    draftWidth = dw;
    draftHeight = dh;
    quality = gui.quality;
    doc = gui.doc.get();
    gui.stillFrames = 0;
    return Ok{};
  }
};

// A strobe slow enough for the eye to see it flash: such a stage is drawn at the clock, frame by
// frame; faster strobes are drawn at their mean, as a still shows them (docs/physics.md, "Strobe").
constexpr float kMaxFlashHz = 15.0f;
bool flashing(const StageState& stage) {
  for (const auto& [id, a] : stage)
    if (a.intensity > 0.0f && a.shutter.strobing() && a.shutter.rateHz <= kMaxFlashHz) return true;
  return false;
}

// What makes the stage change between frames: the view and the document's edits.
struct ChangeWatch {
  Orbit orbit{};
  float fovDeg = 0.0f;
  std::uint64_t revision = 0;
  bool bodies = true;
  CellBeams cells = CellBeams::Auto;
  StageState stage;  // a master fader or a snap changes the stage without an edit or a fade

  bool changing(const Gui& gui) {
    const bool moving = gui.heads && !gui.heads->settled();
    const bool changed = gui.live || gui.doc->fading(gui.nowS) || moving || !(gui.orbit == orbit) || gui.fovYDeg != fovDeg ||
                         gui.doc->revision() != revision || gui.showBodies != bodies || gui.cells != cells || gui.stage != stage;
    stage = gui.stage;
    bodies = gui.showBodies;
    cells = gui.cells;
    orbit = gui.orbit;
    fovDeg = gui.fovYDeg;
    revision = gui.doc->revision();
    return changed;
  }
};

// Refinement stops after this many still frames; the window then sleeps until an event (or a
// tenth of a second, so that follows and fades started by the clock still run).
constexpr int kMaxStillFrames = 64;

// The stage into the viewport: draft while changing, accumulating at the chosen quality while
// still, nothing new once settled. Returns whether the view has settled.
Result<bool> drawStage(Gui& gui, ViewportRenderers& renderers, ChangeWatch& watch, int vx, int vy, int vw, int vh) {
  const auto t0 = std::chrono::steady_clock::now();
  // Edits made this frame show this frame.
  if (!gui.live && gui.doc->revision() != watch.revision) {
    gui.stage = gui.doc->stageState(gui.nowS);
    followHeads(gui);
  }
  // Each flashing frame shows the shutter's mean over about one frame's time.
  const bool flash = flashing(gui.stage);
  const double exposureS = std::clamp(gui.frameMs / 1000.0, 1.0 / 120.0, 0.1);
  FrameOptions frameOptions;
  frameOptions.bodies = gui.showBodies;
  frameOptions.cells = gui.cells;
  frameOptions.clockS = gui.nowS;
  if (flash) frameOptions.time = FrameTime{gui.nowS, exposureS};
  std::vector<std::string> densityWarnings;
  // The field is a still: the hazers at the levels of each list's current cue, its fade done.
  std::vector<HazerCue> hazersOnStage;
  for (size_t l = 0; l < gui.doc->listCount(); ++l)
    if (const auto cue = gui.doc->listCue(l)) hazersOnStage.push_back({&gui.doc->show().cueLists[l], *cue});
  frameOptions.density = gui.atmosphere.at(gui.doc->show(), gui.doc->venue().boundsMin, gui.doc->venue().boundsMax, 0.0,
                                           densityWarnings, hazerSchedule(gui.doc->show(), hazersOnStage, {}));
  for (const std::string& w : densityWarnings) std::fprintf(stderr, "haze: warning: %s\n", w.c_str());
  auto frameState = buildFrame(gui.doc->show(), gui.doc->profiles(), gui.stage, "", frameOptions);
  if (!frameState) return frameState.error();
  gui.beamsDrawn = frameState->beams.size();
  frameState->camera = gui.cameraState();
  const bool changing = watch.changing(gui) || flash;
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  Renderer* r = nullptr;
  const bool settled = !changing && gui.stillFrames >= kMaxStillFrames;
  gui.drewDraft = changing;
  if (changing) {
    r = renderers.draft.get();
    r->render(*frameState);
    gui.stillFrames = 0;
  } else {
    r = renderers.still.get();
    if (!settled) {
      r->render(*frameState, gui.stillFrames > 0);  // keep adding jittered frames while still
      // Frames with maps still being redrawn are not refined: accumulation starts once they are current.
      if (r->lastTimes().mapsPending > 0) gui.stillFrames = 0;
      else ++gui.stillFrames;
    }
  }
  gui.mapsPending = r->lastTimes().mapsPending;
  // What the renderer could not draw goes on the status line (once, not every frame).
  const std::string warning = r->warnings().empty() ? "" : r->warnings().front();
  if (warning != gui.renderWarning && !warning.empty()) gui.say(warning, true);
  gui.renderWarning = warning;
  // The meter reads only new renders; the shown EV glides towards it (no flicker in a fade) and
  // the window keeps drawing until it has arrived. Locked, the meter still reads (the Air tab and
  // the probe show what auto would do) but the EV on screen stays.
  if (!settled) gui.meteredEv = r->meter().ev;
  // A lock remembered from the last run locks at this run's first meter of a picture with its
  // maps current, as if E were pressed then (shows/edit/gui_settings.h says why not last run's EV).
  if (gui.lockExposureWhenMetered && gui.mapsPending == 0) {
    gui.exposureEv = exposureEvFor({.mode = ExposureMode::Auto, .ev = gui.exposureEv}, gui.meteredEv);
    gui.exposureMode = ExposureMode::Manual;
    gui.lockExposureWhenMetered = false;
  }
  const float target = exposureEvFor({.mode = gui.exposureMode, .ev = gui.exposureEv}, gui.meteredEv);
  const auto now = std::chrono::steady_clock::now();
  const float dt = std::chrono::duration<float>(now - gui.shownAt).count();
  gui.shownEv = gui.exposureMode == ExposureMode::Auto ? adaptEv(gui.shownEv, target, dt) : target;
  gui.shownAt = now;
  r->drawDisplay({.exposureEv = gui.shownEv, .bloom = gui.bloom}, 0, vx, vy, vw, vh);
  if (probing()) gui.viewMean = meanLevel(vx, vy, vw, vh);
  if (!settled) gui.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return settled && std::abs(gui.shownEv - target) < 0.01f;
}

// The draft frames' times, from one swap to the next (what the designer sees), fed to the draft
// scale; a frame that began by waiting for events is not timed.
struct DraftPacing {
  std::chrono::steady_clock::time_point lastSwap = std::chrono::steady_clock::now();
  bool waited = true;
  std::vector<double> draftMs;  // every timed draft frame, for --turntable's summary
  // --turn-frames: when the view stopped, and how long after it the first frame at the chosen
  // quality was shown (its maps current: the picture a designer waits for); < 0 not yet.
  std::optional<std::chrono::steady_clock::time_point> stoppedAt;
  double stillMs = -1.0;

  void stillShown(const Gui& gui) {
    if (stoppedAt && stillMs < 0.0 && !gui.drewDraft && gui.stillFrames >= 1)
      stillMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - *stoppedAt).count();
  }

  void swapped(Gui& gui, ViewportRenderers& renderers) {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - lastSwap).count();
    lastSwap = now;
    if (gui.drewDraft && !waited && renderers.width > 0) {
      draftMs.push_back(ms);
      gui.draftScale = static_cast<float>(renderers.draftWidth) / static_cast<float>(renderers.width);
      renderers.draftScale.update(ms);
      gui.draftLimited = renderers.draftScale.limited();
    }
    waited = false;
  }

  // One line for --turntable: the draft frames' median time and the size they settled at.
  void summary(const Gui& gui, const ViewportRenderers& renderers) const {
    std::vector<double> ms(draftMs.begin() + std::min<size_t>(draftMs.size(), 5), draftMs.end());  // past the start-up
    if (ms.empty()) ms = draftMs;
    if (ms.empty()) {
      std::printf("turntable: no draft frame was timed\n");
      return;
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    const double median = ms[ms.size() / 2];
    std::printf("turntable: %zu draft frames, median %.1f ms (%.1f per second), drawn at %dx%d of %dx%d, budget %g ms%s\n",
                draftMs.size(), median, 1000.0 / median, renderers.draftWidth, renderers.draftHeight, renderers.width,
                renderers.height, gui.draftBudgetMs, gui.draftLimited ? ", not met at the smallest size" : "");
    if (stoppedAt && stillMs >= 0.0)
      std::printf("still: the first %s frame shown %.0f ms after the view stopped, %d frames refined by the end\n",
                  qualityName(gui.quality), stillMs, gui.stillFrames);
    else if (stoppedAt)
      std::printf("still: no frame at the chosen quality was shown after the view stopped\n");
  }
};

}  // namespace

int runGui(const Args& args) {
  Options opt;
  if (auto done = parseOptions(args, opt)) return *done;

  // What `haze validate` refuses the GUI refuses too, with the same lines (app/command_line.h).
  if (!CommandLine("haze open", kUsage).readShow(opt.show)) return kExitBadInput;

  Gui gui;
  auto opened = ShowDocument::open(opt.show);
  if (!opened) return fail(opened.error().str());
  gui.adopt(std::move(*opened));
  if (Status s = applyOptions(gui, opt); !s) return fail(s.error().str());

#ifdef NDEBUG
  const bool debugGl = std::getenv("HAZE_GL_DEBUG") != nullptr;
#else
  const bool debugGl = true;  // debug builds always report GL errors (KHR_debug)
#endif
  auto ctx = WindowContext::create(opt.width, opt.height, gui.doc->title(), debugGl);
  if (!ctx) return fail(ctx.error().str());
  gui.window = (*ctx)->window();
  std::string title = gui.doc->title();
  initImGui(gui);

  ViewportRenderers renderers;
  ChangeWatch watch;
  DraftPacing pacing;
  const auto start = std::chrono::steady_clock::now();
  int frame = 0;
  int exitCode = 0;
  bool settled = false;
  while (true) {
    if (settled) {
      glfwWaitEventsTimeout(0.1);
      pacing.waited = true;
    } else {
      glfwPollEvents();
    }
    const bool turning = opt.turnLast < 0 || (frame >= opt.turnFirst && frame <= opt.turnLast);
    if (opt.turntableDeg != 0.0 && turning)
      gui.orbit.yawRad += static_cast<float>(opt.turntableDeg * 3.14159265358979 / 180.0);
    else if (opt.turntableDeg != 0.0 && frame > opt.turnLast && !pacing.stoppedAt)
      pacing.stoppedAt = std::chrono::steady_clock::now();
    if (glfwWindowShouldClose(gui.window) && (gui.quitConfirmed || !gui.doc->modified() || opt.frames > 0)) break;
    int fbW = 0, fbH = 0, winW = 0, winH = 0;
    glfwGetFramebufferSize(gui.window, &fbW, &fbH);
    glfwGetWindowSize(gui.window, &winW, &winH);
    if (fbW <= 0 || fbH <= 0 || winW <= 0 || winH <= 0) {
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    gui.nowS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    drawPanels(gui, winW, winH);

    // The viewport in framebuffer pixels (GL counts rows from the bottom).
    const float sx = static_cast<float>(fbW) / winW, sy = static_cast<float>(fbH) / winH;
    const Rect& vp = gui.layout.viewport;
    const int vx = static_cast<int>(vp.x * sx), vw = std::max(static_cast<int>(vp.w * sx), 1);
    const int vh = std::max(static_cast<int>(vp.h * sy), 1), vy = fbH - static_cast<int>((vp.y + vp.h) * sy);
    if (Status s = renderers.fit(gui, vw, vh); !s) {
      exitCode = fail(s.error().str());
      break;
    }
    auto drawn = drawStage(gui, renderers, watch, vx, vy, vw, vh);
    if (!drawn) {
      exitCode = fail(drawn.error().str());
      break;
    }
    settled = *drawn;
    pacing.stillShown(gui);
    glViewport(0, 0, fbW, fbH);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (gui.doc->title() != title) {
      title = gui.doc->title();
      glfwSetWindowTitle(gui.window, title.c_str());
    }
    ++frame;
    if (opt.frames > 0 && frame >= opt.frames) {
      if (!opt.screenshot.empty()) {
        const Status s = saveScreenshot(fbW, fbH, opt.screenshot);
        if (!s) exitCode = fail(s.error().str());
      }
      glfwSwapBuffers(gui.window);
      pacing.swapped(gui, renderers);
      if (opt.turntableDeg != 0.0) pacing.summary(gui, renderers);
      break;
    }
    glfwSwapBuffers(gui.window);
    pacing.swapped(gui, renderers);
    publishProbe(gui);
    publishFrameCount(frame);
  }

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return exitCode;
}

}  // namespace haze
