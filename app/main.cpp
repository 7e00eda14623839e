// The haze program: the first word picks a subcommand (app/commands.h); no word opens the GUI
// on the bundled demo show.
#include <cstdio>
#include <cstring>
#include <string>

#include "app/commands.h"

namespace {

constexpr const char* kHelp =
    "haze: stage-lighting previsualization\n"
    "  haze                                 GUI on the bundled demo show\n"
    "  haze open SHOW [--cue N] [--select ID]... [--tab T] [--quality Q] [--help-window]\n"
    "                 [--screenshot OUT.png --frames N] [--artnet] [--sacn] [--bind ADDR]   GUI on a show\n"
    "  haze render SHOW [--cue N] [--at S] [--camera NAME] [--width W --height H]\n"
    "                   [--quality draft|default|high|reference] [--exposure EV]\n"
    "                   [--exposure-mode auto|manual] [--bloom F] -o OUT.(png|pfm)\n"
    "  haze render SHOW --all-cues -o DIR/  one image per cue\n"
    "  haze state SHOW --cue N [--at S] [--list NAME] --json\n"
    "  haze validate SHOW\n"
    "  haze import-mvr FILE.mvr -o SHOW.haze.json [--force] [--no-venue] [--verbose]\n"
    "  haze fixture info FILE [--mode M] --json   native profile, .ies, .ldt, .gdtf or QLC+ .qxf\n"
    "  haze fixture search TEXT [--library DIR]... [--json]   the fixture library (QLC+, your folders)\n"
    "  haze fixture change-type SHOW --fixtures 11-20 --type TEXT [--mode M] [-o OUT]\n"
    "  haze bench [--fixtures N] [--width W --height H] [--quality Q] [--compare-reference] [--study] --json\n"
    "  haze compare IMAGE.pfm REFERENCE.pfm [--threshold F] [--max-error E] [--json]   accuracy metric\n"
    "  haze live SHOW [--artnet] [--sacn] [--bind ADDR] [--duration S] [--state-json OUT] [--render OUT.png]\n"
    "  haze sheet SHOW -o SHEET.pdf [--list NAME] [--camera NAME]... [--quality Q]   the review sheet\n"
    "  haze --version                       version, git commit, the OpenGL the renderer gets\n"
    "Each subcommand takes --help.\n";

#ifndef HAZE_HAS_GUI
int noGui() {
  std::fputs("haze: this haze was built without the GUI (HAZE_BUILD_GUI=OFF); the headless commands "
             "work (haze --help)\n", stderr);
  return 2;
}
#endif

int openGui(const haze::Args& args) {
#ifdef HAZE_HAS_GUI
  return haze::runGui(args);
#else
  (void)args;
  return noGui();
#endif
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return openGui({});
  const std::string cmd = argv[1];
  const haze::Args rest(argv + 2, argv + argc);
  if (cmd == "render") return haze::runRender(rest);
  if (cmd == "state") return haze::runState(rest);
  if (cmd == "validate") return haze::runValidate(rest);
  if (cmd == "fixture") return haze::runFixture(rest);
  if (cmd == "bench") return haze::runBench(rest);
  if (cmd == "compare") return haze::runCompare(rest);
  if (cmd == "live") return haze::runLive(rest);
  if (cmd == "import-mvr") return haze::runImportMvr(rest);
  if (cmd == "open") return openGui(rest);
  if (cmd == "sheet") return haze::runSheet(rest);
  if (cmd == "--version" || cmd == "version") return haze::runVersion(rest);
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::fputs(kHelp, stdout);
    return 0;
  }
  std::fprintf(stderr, "haze: unknown command '%s' (try haze --help)\n", cmd.c_str());
  return 2;
}
