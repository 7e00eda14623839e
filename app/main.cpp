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
    "  haze open SHOW [--cue N] [--select ID]... [--tab T] [--quality Q] [--exposure EV]\n"
    "                 [--exposure-mode auto|manual] [--help-window] [--screenshot OUT.png --frames N]\n"
    "                 [--artnet] [--sacn] [--bind ADDR]                 the GUI on a show\n"
    "  haze render SHOW [--cue N | --all-cues | --timecode hh:mm:ss:ff] [--at S] [--list NAME]\n"
    "                   [--camera NAME] [--width W --height H] [--quality draft|default|high|reference]\n"
    "                   [--exposure EV] [--exposure-mode auto|manual|per-frame] [--bloom F]\n"
    "                   -o OUT.(png|pfm|exr) | -o DIR/ (with --all-cues)     stills\n"
    "  haze render SHOW --video OUT.mp4|OUT-%05d.png [--from CUE] [--to CUE] [--fps N] [--hold S]\n"
    "                   [--duration S] [--caption] [--timeline FILE.json | --timecode hh:mm:ss:ff]\n"
    "                   [--frames A-B] [--resume]      frames A..B of an image sequence, as one run makes them\n"
    "  haze render SHOW --play LIST=CUE[@MASTER][+GO_S] [--play ...] [--at S] -o OUT\n"
    "  haze state SHOW --cue N [--at S] [--list NAME] [--follow] [--json]   every fixture's state\n"
    "  haze state SHOW --play LIST=CUE[@MASTER][+GO_S] [--play ...] [--at S] [--json]\n"
    "  haze validate SHOW [--save-as OUT]   every problem of a show; --save-as writes the newest format\n"
    "  haze import-mvr FILE.mvr -o SHOW.haze.json [--force] [--no-venue] [--verbose]\n"
    "  haze export-mvr SHOW -o RIG.mvr [--force] [--focus-list NAME] [--focus-cue N]   the rig as MVR\n"
    "  haze fixture info FILE [--mode M] --json   native profile, .ies, .ldt, .gdtf or QLC+ .qxf\n"
    "  haze fixture search TEXT [--library DIR]... [--json]   the fixture library (QLC+, your folders)\n"
    "  haze fixture list SHOW [--json]      the show's fixtures by id: name, type, mode, universe.address\n"
    "  haze fixture change-type SHOW --fixtures 11-20 --type TEXT [--mode M] [-o OUT]\n"
    "  haze live SHOW [--artnet] [--sacn] [--bind ADDR] [--artnet-port P] [--sacn-port P] [--multicast]\n"
    "                 [--duration S] [--on-loss hold|blackout] [--state-json OUT] [--render OUT.png]\n"
    "                 [--osc PORT] [--timecode] [--mtc [--mtc-from C:P]] [--cue-list NAME]\n"
    "                 [--record-cue N [--label L]] [--no-sync] [--no-preview]   DMX in from a console\n"
    "  haze sheet SHOW -o SHEET.pdf|SHEET.html [--list NAME] [--camera NAME]... [--quality Q]   the review sheet\n"
    "  haze bench [--fixtures N | --show SHOW [--cue N]] [--width W --height H] [--quality Q] [--json]\n"
    "  haze compare IMAGE.pfm REFERENCE.pfm [--threshold F] [--max-error E] [--json]   accuracy metric\n"
    "  haze farm slurm SHOW --video OUT.mp4 [--chunk N] [--quality Q] [--partition P] [--submit]\n"
    "                                       the video on a Slurm cluster: a job array, then the encode\n"
    "  haze farm status FOLDER              which frames of a farm's folder are missing\n"
    "  haze farm encode FOLDER              every frame there and complete, encoded into the video\n"
    "  haze --version                       version, git commit, the OpenGL the renderer gets\n"
    "Each command takes --help for all its options.\n"
    "Every command that reads a show checks it as haze validate does and refuses it with the same lines.\n"
    "Exit status, every command: 0 done; 1 bad input (a file, a show validate refuses, a device, an\n"
    "output that cannot be written); 2 a usage error (an unknown command or option, a bad option value,\n"
    "options that do not go together, a missing argument); haze compare: 3 over --max-error.\n";

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
  if (cmd == "farm") return haze::runFarm(rest);
  if (cmd == "state") return haze::runState(rest);
  if (cmd == "validate") return haze::runValidate(rest);
  if (cmd == "fixture") return haze::runFixture(rest);
  if (cmd == "bench") return haze::runBench(rest);
  if (cmd == "compare") return haze::runCompare(rest);
  if (cmd == "live") return haze::runLive(rest);
  if (cmd == "import-mvr") return haze::runImportMvr(rest);
  if (cmd == "export-mvr") return haze::runExportMvr(rest);
  if (cmd == "open") return openGui(rest);
  if (cmd == "sheet") return haze::runSheet(rest);
  if (cmd == "--version" || cmd == "version") return haze::runVersion(rest);
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::fputs(kHelp, stdout);
    return 0;
  }
  std::fprintf(stderr, "haze: unknown command '%s' (try haze --help)\n", cmd.c_str());
  return haze::kExitUsage;
}
