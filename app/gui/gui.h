// What the GUI's panels share: the open document, the view (orbit camera, tool, quality), the
// file dialogs' state and the status line; and one function per panel, each in its own file:
//   gui_app.cpp         the window, the frame loop, options (--screenshot, --frames, --cue...)
//   gui_layout.cpp      where the panels and the viewport go for a window size
//   gui_menus.cpp       menu bar (File, Edit, View, Help, tools) and keyboard shortcuts
//   gui_files.cpp       open, new, save, save as, recent files, import MVR, the unsaved guard
//   gui_settings.cpp    the view settings remembered between runs (gui-settings.json)
//   gui_viewport.cpp    orbit/pan/zoom, cameras, clicks (select, place, focus), drags, overlay
//   gui_cues.cpp        cue list, transport (GO, BACK, GOTO, fade progress), cue editing
//   gui_fixtures.cpp    the fixture list (selection)
//   gui_library.cpp     the show's profiles, adding files from disk, placing
//   gui_patch.cpp       the patch table with conflicts
//   gui_atmosphere.cpp  atmosphere, render quality, exposure, bloom
//   gui_inspector.cpp   the selection: transform, pan/tilt, focus, attributes
//   gui_help.cpp        the shortcuts window (F1)
//   gui_import.cpp      the window listing an MVR import's warnings
//   gui_command.cpp     the console command line under the show panel
//   desktop_dialog.cpp  the desktop's file dialog (zenity or kdialog) as a child process
// Panels draw with ImGui and change the show only through ShowDocument (commands, undo).
#pragma once

#include <chrono>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>  // GetItemID: which widget an edit came from (undo merging)

#include "shows/frame/atmosphere_field.h"
#include "shows/frame/frame_builder.h"
#include "app/gui/desktop_dialog.h"
#include "shows/edit/fixture_rows.h"
#include "shows/edit/gui_settings.h"
#include "shows/edit/label_layout.h"
#include "shows/edit/show_document.h"
#include "shows/movement.h"
#include "app/render_job.h"
#include "app/xchange_station.h"
#include "shows/scene/frame_state.h"

struct GLFWwindow;

namespace haze {

class LiveSession;

struct Orbit {
  glm::vec3 target{0.0f, 2.0f, 0.0f};
  float distanceM = 15.0f, yawRad = 0.0f, pitchRad = 0.2f;
  static Orbit from(const CameraDef& c);
  glm::vec3 position() const;
  bool operator==(const Orbit&) const = default;
};

enum class Tool { Select, Place, Focus };
enum class FileAction { None, New, Open, OpenPath, SaveAs, AddProfile, ImportMvr, ExportMvr, Quit };

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
  bool contains(ImVec2 p) const { return p.x >= x && p.y >= y && p.x < x + w && p.y < y + h; }
};

struct Layout {
  float menuH = 0;
  Rect left, right, viewport;  // window coordinates, pixel (0, 0) at the top left
  Rect command;                // the command line, under the show panel
};
// leftWidthPx: the show panel's width (showPanelWidth); the inspector and viewport take the rest.
Layout layoutFor(float widthPx, float heightPx, float menuHeightPx, float leftWidthPx);

// The show panel's tabs, in their order on screen (gui_layout.cpp; --tab names them too).
inline constexpr const char* kShowTabs[] = {"Cues", "Fixtures", "Library", "Patch", "Air", "Playback"};

struct Gui {
  GLFWwindow* window = nullptr;
  std::unique_ptr<ShowDocument> doc;
  // The show's density field as a still at GO (docs/shows.md, "Density"): the viewport
  // accumulates still frames, so the haze is not drifted in the window.
  AtmosphereField atmosphere;
  std::unique_ptr<LiveSession> live;  // DMX from a console drives the rig instead of the cues
  std::string liveBind;
  Layout layout;
  double nowS = 0.0;
  StageState stage;  // what is on stage this frame (playback + programmer, or live)
  // Heads at the fixtures' own speeds (docs/movement.md); View > Real movement turns it off.
  bool realMovement = true;
  bool showBodies = true;  // View > Fixture bodies (docs/fixtures.md, "Bodies")
  CellBeams cells = CellBeams::Auto;  // View > Cells (docs/cells.md, "Cost")
  size_t beamsDrawn = 0;              // the beams of the last frame built (the probe's, tests/gui/view_cells.sh)
  bool showNumbers = true;  // View > Fixture numbers: each marker's id beside it
  std::unique_ptr<MovementFollower> heads;
  const ShowDocument* headsDoc = nullptr;  // the document `heads` follows

  // View.
  Orbit orbit;
  float fovYDeg = 40.0f;
  int camera = -1;  // index of the show camera last chosen (-1: none)
  Tool tool = Tool::Select;
  std::string placeProfile;  // the library's selection
  Quality quality = Quality::Default;
  // Exposure (shows/scene/exposure.h): under auto, exposureEv is an offset from the meter and
  // the shown EV follows the metered one smoothly; under manual it is absolute.
  ExposureMode exposureMode = ExposureMode::Auto;
  float exposureEv = 0.0f;
  float meteredEv = 0.0f;  // the meter on the last render
  float shownEv = std::numeric_limits<float>::quiet_NaN();  // the absolute EV on screen; NaN: none yet
  std::chrono::steady_clock::time_point shownAt;
  bool exposureLocked() const { return exposureMode == ExposureMode::Manual; }
  // The viewport's mean display level (0..1, sRGB as drawn) of the last frame; measured only for
  // the tests' probe (HAZE_GUI_PROBE_FILE), as reading the frame back costs a stall.
  float viewMean = std::numeric_limits<float>::quiet_NaN();
  float bloom = 0.0f;  // lens glare on the display (DisplaySettings::bloom); never in the show
  double frameMs = 0.0;
  int stillFrames = 0;
  // Draft frames are drawn at a share of the viewport's size that keeps them near this many
  // milliseconds (shows/scene/draft_scale.h; 0: always the full size). View > Draft budget.
  double draftBudgetMs = 50.0;
  float draftScale = 1.0f;     // the last draft frame's linear scale
  bool draftLimited = false;   // the budget was not met even at the smallest scale
  bool drewDraft = false;      // the last frame was a draft (the view or the stage moved)
  int mapsPending = 0;         // beams shown with out-of-date maps while the renderer catches up
  bool showHelp = false;
  // The last MVR import's warnings, folded (shows/import/mvr_import.h groupMvrWarnings), in a window.
  std::vector<std::string> importWarnings;
  std::string importedFrom;
  bool showImportWarnings = false;
  // File > MVR-xchange (gui_xchange.cpp): the station while it runs, for the show open then.
  bool showXchange = false;
  std::unique_ptr<XchangeService> xchange;
  std::string xchangeShow;  // the show file it serves
  char xchangeGroup[64] = "Default";
  char xchangeBind[64] = "127.0.0.1";  // as `haze live --bind`: this machine only until changed
  std::string openTab;  // a tab of the show panel to bring to the front once ("Patch"...)

  // The console command line (gui_command.cpp): the field, the lines run (oldest first), which
  // of them Up/Down show (-1: none), the last result or error and what Tab offered.
  char commandField[512] = "";
  std::vector<std::string> commandHistory;
  int commandBrowse = -1;
  bool focusCommand = false;
  std::string commandResult, commandOffered;
  bool commandError = false;

  // Fixture identity (docs/gui-commands.md, "Fixture identity"): the Fixtures and Patch tabs
  // filter (one field, shared, so a filter typed in one holds in the other); what the last frame
  // drew, for the tests' probe (HAZE_GUI_PROBE_FILE, gui_app.cpp): the rows each tab listed, the
  // selected fixtures' label boxes in the viewport, and the filter field's place on screen.
  char fixtureFilter[128] = "";
  std::vector<int> fixtureRows, patchRows;
  std::vector<PlacedLabel> placedLabels;
  Rect filterField;
  // Where the Library tab drew its search field, first hit and "Change type" button (window
  // pixels; zero size when not drawn), and how many hits it lists: for the probe.
  struct LibraryProbe {
    Rect search, firstHit, change;
    int hits = 0;
  } libraryProbe;
  // The show panel's tabs as the last frame laid them out: a tab drawn narrower than its label
  // needs is truncated ("Fixtu...") (tests/gui/panel_tabs.sh).
  struct TabShown {
    std::string name;
    float widthPx = 0, neededPx = 0;
  };
  std::vector<TabShown> tabsShown;
  // The show panel's width as the user dragged its right edge to (0: showPanelWidth's default,
  // wide enough for the tab names where the window allows).
  float showPanelW = 0.0f;

  // The view settings remembered between runs (gui_settings.cpp): the file, what it holds (as
  // last read or written), the view's settings as of the last write or the start, and a lock
  // remembered from the last run that waits for the first metered frame.
  std::filesystem::path settingsFile;
  GuiSettings settingsSaved, settingsBefore;
  bool lockExposureWhenMetered = false;

  // Cues panel: the cue picked for editing (not the one on stage).
  std::optional<size_t> cueCursor;

  // Files.
  std::vector<std::string> recent;
  FileAction pathAction = FileAction::None;  // the path popup asks for this
  bool openPathPopup = false;
  char pathField[1024] = "";
  FileAction guarded = FileAction::None;     // waits for the unsaved-changes answer
  std::string guardedPath;
  bool openGuardPopup = false;
  bool quitConfirmed = false;
  DesktopDialog dialog;                      // the desktop's file dialog, while it is open
  FileAction dialogAction = FileAction::None;

  // Key presses since the last frame, from GLFW's key callback. ImGui 1.86 keeps only whether a
  // key is down at each frame, so a tap shorter than a frame (a slow frame while refining, or
  // xdotool's instant taps) would be lost; shortcuts read this queue instead.
  struct KeyPress {
    int key = 0;   // GLFW_KEY_*
    int mods = 0;  // GLFW_MOD_*
  };
  std::vector<KeyPress> keys;

  // The status line: the last action's outcome.
  std::string status;
  bool statusError = false;
  std::string renderWarning;  // the renderer's last warning, said once when it changes
  void say(std::string line, bool error = false) {
    status = std::move(line);
    statusError = error;
  }
  void report(const Status& s, const std::string& done) {
    if (s) say(done);
    else say(s.error().str(), true);
  }

  // Widget edits that merge into one undo step while the same widget stays active (a drag).
  ImGuiID mergeItem = 0;
  bool mergeFor(ImGuiID item) {
    const bool merge = mergeItem == item;
    mergeItem = item;
    return merge;
  }

  // Swaps in another show (or a new one): the view goes to its first camera.
  void adopt(std::unique_ptr<ShowDocument> next);
  CameraState cameraState() const;
};

// Panels and handlers, in the order the frame loop calls them.
void handleShortcuts(Gui& gui);
void drawMenuBar(Gui& gui);
void drawShowPanel(Gui& gui);  // the left panel's tabs
float showPanelWidth(const Gui& gui, float windowWidthPx);  // the show panel's width this frame
void drawCuesTab(Gui& gui);
void drawPlaybacksTab(Gui& gui);  // every cue list: GO, BACK, master
void drawFixturesTab(Gui& gui);
// The filter field both fixture tabs show; returns what it lists (label_layout.h listedFixtures).
std::vector<const FixtureDef*> drawFixtureFilter(Gui& gui);
void drawLibraryTab(Gui& gui);
void drawPatchTab(Gui& gui);
void drawAtmosphereTab(Gui& gui);
// Auto or manual exposure, keeping the picture (gui_atmosphere.cpp): manual is the lock of View >
// Lock exposure, holding the EV on screen at the moment of the switch for every frame after it.
void setExposureMode(Gui& gui, ExposureMode mode);
void drawInspector(Gui& gui);
void drawHelp(Gui& gui);
void drawImportWarnings(Gui& gui);
void drawXchangeWindow(Gui& gui);
void drawCommandLine(Gui& gui);
void drawFileDialogs(Gui& gui);
void handleViewport(Gui& gui);  // mouse in the viewport, then the overlay

// The view settings remembered between runs (gui_settings.cpp): read at start, after the command
// line's options (which win for this run); kept once a frame, written only when one changed.
GuiSettings viewSettingsOf(const Gui& gui);
void loadViewSettings(Gui& gui, bool qualityFromCommandLine, bool exposureFromCommandLine);
void keepViewSettings(Gui& gui);

// File actions that the menus, shortcuts and the guard share (gui_files.cpp).
void requestFileAction(Gui& gui, FileAction action, std::string path = "");
void saveCurrent(Gui& gui);
void recordCueFromProgrammer(Gui& gui);  // gui_cues.cpp
void recordDmxLook(Gui& gui);            // gui_cues.cpp: live, the look DMX puts on stage
void updateCursorCue(Gui& gui);          // gui_cues.cpp

}  // namespace haze
