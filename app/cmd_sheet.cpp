// `haze sheet SHOW -o SHEET.pdf|SHEET.html [--list NAME] [--camera NAME]... [--quality Q] [--progress]`:
// the review sheet for the board operator (docs/output.md): per cue its number, label, timing, a
// thumbnail from each camera and what changes from the cue before (app/sheet_changes.h); then
// the patch, by universe and address. One SheetDoc, written as a PDF or as one HTML file.
#include <algorithm>
#include <cstdio>
#include <tuple>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/progress.h"
#include "app/render_session.h"
#include "app/sheet_changes.h"
#include "shows/frame/state_json.h"
#include "renderer/output/sheet_html.h"
#include "renderer/output/sheet_pdf.h"
#include "shows/hazer_levels.h"
#include "shows/playback.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze sheet SHOW -o SHEET.pdf|SHEET.html [--list NAME] [--camera NAME]... [--quality Q] [--progress]\n"
    "  One row per cue of the list (default: the first): number, label, fade, delay, follow, a\n"
    "  thumbnail from each --camera (default: the show's first; at most 3), and the fixtures that\n"
    "  change from the cue before and to what, as ranges of one type (\"11-20 Alpha Spot @ 70 %,\n"
    "  palette Blue, gobo Spokes\"); the patch by universe and address on its own page. A4 landscape.\n"
    "  -o NAME.html writes the same sheet as one HTML page, its thumbnails embedded as PNG data.\n";

constexpr int kMaxCameras = 3;
constexpr int kThumbPixelsWide = 320, kThumbPixelsHigh = 180;  // twice the printed size

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", s);
  return text;
}

}  // namespace

int runSheet(const Args& args) {
  std::string showPath, out, list, quality = "default";
  std::vector<std::string> cameras;
  bool progress = false;
  CommandLine cli("haze sheet", kUsage);
  cli.text("-o|--output", out, "a .pdf or .html file")
      .text("--list", list, "a cue list name")
      .custom("--camera", "a camera name", [&cameras](const std::string& v) {
        cameras.push_back(v);
        return true;
      })
      .choice("--quality", quality, {"draft", "default", "high", "reference"})
      .flag("--progress", progress)
      .positional(showPath, "show");
  if (auto done = cli.parse(args)) return *done;
  const auto fail = [&cli](const std::string& line) { return cli.fail(line); };
  if (out.empty()) return cli.usage("no output given: -o SHEET.pdf or -o SHEET.html");
  const std::string extension = std::filesystem::path(out).extension().string();
  if (extension != ".pdf" && extension != ".html")
    return cli.usage(out + ": the sheet is a PDF or an HTML page (-o SHEET.pdf, -o SHEET.html)");
  if (cameras.size() > kMaxCameras)
    return cli.usage("at most " + std::to_string(kMaxCameras) + " cameras fit a row (got " + std::to_string(cameras.size()) + ")");
  auto q = parseQuality(quality);
  if (!q) return fail(q.error().str());

  auto checked = cli.readShow(showPath);
  if (!checked) return kExitBadInput;
  const Show* show = &checked->show;
  const ProfileSet* profiles = &checked->profiles;
  const CueList* cueList = show->findCueList(list);
  if (!cueList) return fail(showPath + ": no cue list" + (list.empty() ? "" : " named '" + list + "'"));
  if (cameras.empty()) cameras.push_back(show->cameras.empty() ? "" : show->cameras.front().name);

  SheetDoc doc;
  doc.title = show->file.filename().string();
  doc.subtitle = "cue list " + cueList->name + ", " + std::to_string(cueList->cues.size()) + " cues, " +
                 std::to_string(show->fixtures.size()) + " fixtures";
  doc.cameras = cameras;
  doc.cues.resize(cueList->cues.size());
  std::vector<StageState> states;
  for (size_t i = 0; i < cueList->cues.size(); ++i) states.push_back(trackedState(*show, *profiles, *cueList, i));

  Progress report("haze sheet", "thumbnails", static_cast<long>(cueList->cues.size() * cameras.size()), progress);
  long done = 0;
  for (size_t c = 0; c < cameras.size(); ++c) {
    RenderJobOptions options{.camera = cameras[c], .width = kThumbPixelsWide, .height = kThumbPixelsHigh, .quality = *q};
    auto session = RenderSession::open(*show, options);
    if (!session) return fail(session.error().str());
    for (size_t i = 0; i < cueList->cues.size(); ++i) {
      (*session)->setHazers(hazerSchedule(*show, {{cueList, i}}, {}));
      if (Status s = (*session)->draw(*show, *profiles, states[i]); !s) return fail(s.error().str());
      doc.cues[i].thumbnails.push_back({.width = kThumbPixelsWide, .height = kThumbPixelsHigh,
                                        .rgb8 = (*session)->display(*show)});
      report.step(++done);
    }
  }
  report.finish();

  nlohmann::ordered_json before = stageStateJson(*show, *profiles, defaultState(*show));
  for (size_t i = 0; i < cueList->cues.size(); ++i) {
    const Cue& cue = cueList->cues[i];
    SheetCue& row = doc.cues[i];
    row.number = cue.number;
    row.label = cue.label;
    row.timing = "fade " + seconds(cue.fadeS) + ", delay " + seconds(cue.delayS) + ", follow " +
                 (cue.followS ? seconds(*cue.followS) : std::string("-"));
    const nlohmann::ordered_json after = stageStateJson(*show, *profiles, states[i]);
    row.changes = sheetChanges(*show, *profiles, cue, before, after);
    before = after;
  }
  // The patch as the desk patches: by universe and address, the unpatched last by id.
  std::vector<const FixtureDef*> patchOrder;
  for (const FixtureDef& f : show->fixtures) patchOrder.push_back(&f);
  std::stable_sort(patchOrder.begin(), patchOrder.end(), [](const FixtureDef* a, const FixtureDef* b) {
    const auto key = [](const FixtureDef* f) {
      return std::tuple(!f->patch, f->patch ? f->patch->universe : 0, f->patch ? f->patch->address : 0, f->id);
    };
    return key(a) < key(b);
  });
  for (const FixtureDef* fp : patchOrder) {
    const FixtureDef& f = *fp;
    doc.patch.push_back({.fixture = std::to_string(f.id) + (f.name.empty() ? "" : " " + f.name),
                         .profile = f.profile, .mode = f.mode.empty() ? "-" : f.mode,
                         .universe = f.patch ? std::to_string(f.patch->universe) : "-",
                         .address = f.patch ? std::to_string(f.patch->address) : "unpatched"});
  }
  if (Status s = extension == ".html" ? writeSheetHtml(doc, out) : writeSheetPdf(doc, out); !s) return fail(s.error().str());
  std::printf("%s\n", out.c_str());
  return 0;
}

}  // namespace haze
