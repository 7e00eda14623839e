// `haze fixture info FILE [--json]`: the facts of any profile file (native JSON, IES, LDT, GDTF)
// on stdout; a bad file or bad arguments give one line on stderr and exit status 1.
#include <iostream>

#include "app/command_line.h"
#include "app/commands.h"
#include "fixtures/facts.h"
#include "fixtures/profile.h"

namespace haze {

namespace {

constexpr const char* kUsage = "usage: haze fixture info FILE [--json]";

void printText(const nlohmann::ordered_json& f) {
  auto num = [&](const char* k) { return f[k].get<double>(); };
  std::cout << f["name"].get<std::string>() << " (" << f["manufacturer"].get<std::string>() << ")\n"
            << "  peak " << num("peak_candela") << " cd, " << num("lumens") << " lm\n"
            << "  beam " << num("beam_angle") << " deg (C0 " << num("beam_angle_c0") << ", C90 " << num("beam_angle_c90") << ")\n"
            << "  field " << num("field_angle") << " deg (C0 " << num("field_angle_c0") << ", C90 " << num("field_angle_c90") << ")\n"
            << "  symmetry " << f["symmetry"].get<std::string>() << ", grid " << f["grid"]["gamma"].get<int>() << " gamma x "
            << f["grid"]["c"].get<int>() << " C\n"
            << "  lens radius " << num("lens_radius") << " m (" << f["lens_radius_source"].get<std::string>() << ")\n";
  for (const char* axis : {"pan", "tilt", "zoom"}) {
    const auto& m = f["movement"][axis];
    std::cout << "  " << axis << " speed " << m["speed"].get<double>() << " deg/s, acceleration "
              << m["acceleration"].get<double>() << " deg/s^2 (" << m["source"].get<std::string>() << ")\n";
  }
  if (!f["cells"].empty()) std::cout << "  " << f["cells"].size() << " cells:\n";
  for (const auto& c : f["cells"]) {
    std::cout << "    " << c["cell"].get<int>() << " " << c["name"].get<std::string>() << ": lens at ["
              << c["lens_offset"][0].get<double>() << ", " << c["lens_offset"][1].get<double>() << ", "
              << c["lens_offset"][2].get<double>() << "] m, field " << c["field_angle"].get<double>() << " deg, "
              << c["lumens"].get<double>() << " lm\n";
  }
  {
    const auto& b = f["body"];
    std::cout << "  body (" << b["source"].get<std::string>() << "):";
    for (const char* part : {"base", "yoke_left", "head"}) {
      if (b[part].is_null()) continue;
      const auto& size = b[part]["size"];
      std::cout << " " << (std::string(part) == "yoke_left" ? "yoke arm" : part) << " " << size[0].get<double>() << " x "
                << size[1].get<double>() << " x " << size[2].get<double>() << " m";
    }
    std::cout << "\n";
    for (const auto& m : b["models"]) {
      const auto& size = m["size"];
      std::cout << "    " << m["part"].get<std::string>() << " model " << m["file"].get<std::string>() << ": "
                << m["triangles"].get<std::size_t>() << " triangles, " << size[0].get<double>() << " x "
                << size[1].get<double>() << " x " << size[2].get<double>() << " m\n";
    }
  }
  for (auto [key, what] : {std::pair{"gobo_wheels", "gobo wheel"}, std::pair{"color_wheels", "colour wheel"},
                            std::pair{"animation_wheels", "animation wheel"}})
    for (size_t w = 0; w < f[key].size(); ++w) {
      const auto& wheel = f[key][w];
      std::cout << "  " << what << " " << w + 1 << " \"" << wheel["name"].get<std::string>() << "\": " << wheel["slots"].size()
                << " slots:";
      for (const auto& s : wheel["slots"]) std::cout << " \"" << s.get<std::string>() << "\"";
      std::cout << "\n";
    }
  // Beam optics beyond the gobo.
  if (!f["frost"].is_null()) std::cout << "  frost up to " << f["frost"]["max"].get<double>() << " deg\n";
  if (!f["focus"].is_null())
    std::cout << "  focus: sharp at " << f["focus"]["sharp"].get<double>() << ", blur " << f["focus"]["blur"].get<double>()
              << " gate radii per unit of focus\n";
  for (const auto& p : f["prisms"])
    std::cout << "  prism \"" << p["name"].get<std::string>() << "\": " << p["facets"].get<int>() << " facets"
              << (p["linear"].get<bool>() ? " linear" : "") << ", " << p["deflection"].get<double>() << " deg\n";
  if (f["blades"].get<bool>()) std::cout << "  framing blades\n";
  if (!f["shutter"].is_null()) {
    std::cout << "  shutter";
    for (const auto& m : f["shutter"]["modes"]) std::cout << " " << m.get<std::string>();
    std::cout << " (up to " << f["shutter"]["max_hz"].get<double>() << " Hz)\n";
  }
}

}  // namespace

int runFixture(const Args& args) {
  if (args.empty() || args[0] != "info") {
    std::cerr << "haze fixture: expected the subcommand \"info\"; " << kUsage << "\n";
    return kExitUsage;
  }
  std::string file;
  bool json = false;
  CommandLine cli("haze fixture info", std::string(kUsage) + "\n");
  cli.flag("--json", json).positional(file, "file");
  if (auto done = cli.parse(Args(args.begin() + 1, args.end()))) return *done;
  auto profile = loadProfile(file);
  if (!profile) {
    std::cerr << profile.error().str() << "\n";
    return 1;
  }
  // What reading the profile clamped (prisms, frost beyond haze's ranges) is said, not dropped.
  for (const std::string& w : (*profile)->warnings) std::cerr << "warning: " << w << "\n";
  nlohmann::ordered_json facts = fixtureFacts(**profile);
  if (json)
    std::cout << facts.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
  else
    printText(facts);
  return 0;
}

}  // namespace haze
