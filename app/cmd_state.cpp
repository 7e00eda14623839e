// `haze state SHOW --cue N [--at S] [--list NAME] [--follow] [--json]`: every fixture's attributes
// S seconds after GO into cue N from the full state of the cue before it (docs/show-format.md). With
// --follow, follows fire as they would on stage (cue N's follow may GO the next cue, and so on).
// `--play LIST=CUE[@MASTER][+GO_S]` (repeated) plays several lists at once instead (shows/frame/list_plays.h).
// A show `haze validate` refuses gives its lines on stderr and exit 1; bad arguments exit 2.
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "shows/frame/atmosphere_field.h"
#include "shows/hazer_levels.h"
#include "shows/scene/venue.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "shows/frame/list_plays.h"
#include "shows/frame/state_json.h"
#include "shows/cue_player.h"
#include "shows/movement.h"
#include "shows/playback.h"
#include "shows/show_json.h"

namespace haze {

namespace {

constexpr const char* kUsage =
    "usage: haze state SHOW --cue N [--at S] [--list NAME] [--follow] [--movement real|instant] [--json]\n"
    "       haze state SHOW --play LIST=CUE[@MASTER][+GO_S] [--play ...] [--at S] [--movement ...] [--json]\n"
    "  The state of every fixture S seconds after GO into cue N (default: the cue's full state).\n"
    "  --list NAME  the cue list (default: the first)\n"
    "  --follow     let follows fire after cue N, as on stage\n"
    "  --play       several cue lists at once: LIST stands in the cue before CUE, its master at\n"
    "               MASTER (0..1, default 1), and GOes into CUE GO_S seconds after 0 (default 0;\n"
    "               at one time in the order given); intensity HTP, the rest LTP; follows fire;\n"
    "               --at S counts from 0\n"
    "  --movement   real (default): pan, tilt and zoom at the fixtures' speeds; instant: at once\n"
    "  --json       {\"<fixture id>\": {\"intensity\", \"pan\", \"tilt\", \"color\", \"zoom\", \"gobo\", "
    "\"gobo_rotation\", \"iris\",\n"
    "               \"frost\", \"focus\" (where the fixture has one), \"prism\", \"prism_rotation\", \"blades\", \"blade_rotation\", \"shutter\",\n"
    "               with --at also \"gate\": the shutter's opening (0..1) at that moment;\n"
    "               \"gobo2\", \"gobo2_rotation\", \"animation\", \"animation_rotation\" and each spin with\n"
    "               its angle at --at (\"gobo_spin\", \"gobo_angle\", ..., \"animation_angle\") where they\n"
    "               are in}}\n";

struct StateArgs {
  std::string file, cueNumber, listName, movement = "real";
  double atS = 1e9;  // no --at: the cue's full state
  bool json = false, follow = false;
  std::vector<ListPlay> plays;
  std::string playError;
  bool atGiven() const { return atS < 1e9; }
};

// What the playback gives at that moment: the fixtures and the hazers' levels over the same
// playback (docs/shows.md, "Hazers in cues").
struct PlayedState {
  StageState state;
  HazerSchedule hazers;
};

// Cue N of one list, S seconds after its GO (with --follow, its follows firing as on stage).
Result<PlayedState> cueState(const StateArgs& a, const Show& show, const ProfileSet& profiles) {
  const CueList* list = show.findCueList(a.listName);
  if (!list)
    return Error{a.file, "", a.listName.empty() ? "the show has no cue lists" : "no cue list \"" + a.listName + "\""};
  auto cue = findCue(*list, a.cueNumber);
  if (!cue) return Error{a.file, "", cue.error().message};
  PlayedState out;
  if (!a.atGiven())
    out.hazers = hazerSchedule(show, {{list, *cue}}, {});
  else if (*cue > 0)
    out.hazers = hazerSchedule(show, {{list, *cue - 1}}, {{list, *cue, 0.0}});
  else
    out.hazers = hazerSchedule(show, {}, {{list, *cue, 0.0}});
  const bool real = a.movement == "real";
  if (!a.follow) {
    out.state = real ? movingStateAt(show, profiles, *list, *cue, a.atS) : stateAt(show, profiles, *list, *cue, a.atS);
    return out;
  }
  CuePlayer player(show, profiles, *list);
  if (*cue > 0) player.jumpTo(*cue - 1, 0.0);
  player.gotoCue(*cue, 0.0);
  out.state = real ? followCommand(
                         show, profiles, [&](double t) { return player.state(t); },
                         [&](double t) { return !player.fading(t) && !player.nextFollowAtS(); }, a.atS)
                   : player.state(a.atS);
  return out;
}

// The density field at that time (docs/shows.md, "Density"), summed up; null without one.
Result<nlohmann::ordered_json> atmosphereJson(const Show& show, const HazerSchedule& hazers, double clockS) {
  const auto& spec = show.atmosphere.density;
  if (!spec) return nlohmann::ordered_json();
  glm::vec3 lo{0.0f}, hi{0.0f};
  if (!spec->boundsMinM && !show.venueGltf.empty()) {
    auto venue = loadVenue(show.resolve(show.venueGltf));
    if (!venue) return venue.error();
    lo = venue->boundsMin;
    hi = venue->boundsMax;
  }
  AtmosphereField atmosphere;
  std::vector<std::string> warnings;
  const auto field = atmosphere.at(show, lo, hi, clockS, warnings, hazers);
  for (const std::string& w : warnings) std::cerr << "haze: warning: " << w << "\n";
  double sum = 0.0;
  for (float v : field->values) sum += v;
  nlohmann::ordered_json out = {
      {"density_time_s", densityTimeS(*spec, clockS)},
      {"grid", {field->nx, field->ny, field->nz}},
      {"bounds", {{field->minM.x, field->minM.y, field->minM.z}, {field->maxM.x, field->maxM.y, field->maxM.z}}},
      {"mean_density", sum / static_cast<double>(field->values.size())},
      {"max_density", field->maxValue()}};
  nlohmann::ordered_json levels = nlohmann::ordered_json::array();
  for (size_t h = 0; h < spec->hazers.size(); ++h) {
    const HazerLevel l = hazers.at(h, densityTimeS(*spec, clockS));
    levels.push_back({{"output", l.output}, {"fan", l.fan}});
  }
  out["hazers"] = levels;
  return out;
}

void print(const nlohmann::ordered_json& out, bool json) {
  if (json) {
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (const auto& [id, a] : out.items()) {
    std::cout << id;
    for (const auto& [k, v] : a.items()) std::cout << "  " << k << " " << v.dump();
    std::cout << "\n";
  }
}

}  // namespace

int runState(const Args& args) {
  StateArgs a;
  CommandLine cli("haze state", kUsage);
  cli.custom("--play", "LIST=CUE[@MASTER][+GO_S]", [&a](const std::string& v) {
    auto p = parseListPlay(v);
    if (p) a.plays.push_back(*p);
    if (!p && a.playError.empty()) a.playError = p.error().message;  // reported below with the reason
    return true;
  });
  cli.text("--cue", a.cueNumber, "a cue number")
      .number("--at", a.atS, 0.0, 1e9, "a time in seconds (a number, not negative)")
      .text("--list", a.listName, "a cue list name")
      .flag("--json", a.json)
      .flag("--follow", a.follow)
      .choice("--movement", a.movement, {"real", "instant"})
      .positional(a.file, "show");
  if (auto done = cli.parse(args)) return *done;
  if (!a.playError.empty()) return cli.usage("--play " + a.playError);
  if (!a.plays.empty() && (!a.cueNumber.empty() || !a.listName.empty()))
    return cli.usage("--play names its lists and cues itself; expected no --cue or --list with it");
  if (a.cueNumber.empty() && a.plays.empty()) return cli.usage("expected --cue N (or --play LIST=CUE)");

  auto checked = cli.readShow(a.file);
  if (!checked) return kExitBadInput;
  const Show& show = checked->show;
  Result<PlayedState> played = Error{};
  if (a.plays.empty()) {
    played = cueState(a, show, checked->profiles);
  } else if (auto state = playListsAt(show, checked->profiles, a.plays, a.atS, a.movement == "real")) {
    played = PlayedState{std::move(*state), hazersOfPlays(show, a.plays, a.atGiven())};
  } else {
    played = state.error();
  }
  // Errors as the show's checks give them: "file: message", without the command's name.
  const auto fail = [](const Error& e) {
    std::cerr << e.str() << "\n";
    return kExitBadInput;
  };
  if (!played) return fail(played.error());
  // The strobe runs on the playback clock, which starts at GO: --at is also the gate's time.
  nlohmann::ordered_json out =
      stageStateJson(show, checked->profiles, played->state, a.atGiven() ? std::optional<double>(a.atS) : std::nullopt);
  auto atmosphere = atmosphereJson(show, played->hazers, a.atGiven() ? a.atS : 0.0);
  if (!atmosphere) return fail(atmosphere.error());
  if (!atmosphere->is_null()) out["atmosphere"] = std::move(*atmosphere);
  print(out, a.json);
  return 0;
}

}  // namespace haze
