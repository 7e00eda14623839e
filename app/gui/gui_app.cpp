// The GUI: a window on one show, drawn by the same renderer as `haze render`. The viewport
// orbits around a target; cues play with GO / BACK through the pure playback function. Edits
// of the show (placing, aiming, recording) come in through the command layer (issue 6).
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "app/commands.h"
#include "app/frame_builder.h"
#include "app/render_session.h"
#include "app/udp_receiver.h"
#include "app/window_context.h"
#include "renderer/gl/gl.h"
#include "renderer/renderer.h"
#include "renderer/scene/image.h"
#include "shows/mvr_import.h"
#include "shows/playback.h"
#include "shows/show_save.h"
#include "shows/show.h"

namespace haze {
namespace {

struct Orbit {
  glm::vec3 target{0.0f, 2.0f, 0.0f};
  float distanceM = 15.0f, yawRad = 0.0f, pitchRad = 0.2f;

  static Orbit from(const CameraDef& c) {
    Orbit o;
    o.target = c.target;
    const glm::vec3 d = c.position - c.target;
    o.distanceM = std::max(glm::length(d), 0.5f);
    o.yawRad = std::atan2(d.x, d.z);
    o.pitchRad = std::asin(std::clamp(d.y / o.distanceM, -1.0f, 1.0f));
    return o;
  }
  glm::vec3 position() const {
    return target + distanceM * glm::vec3(std::cos(pitchRad) * std::sin(yawRad), std::sin(pitchRad),
                                          std::cos(pitchRad) * std::cos(yawRad));
  }
};

struct Options {
  std::string show;
  std::string screenshot;
  int frames = 0;
  int width = 1280, height = 720;
  bool artNet = false, sacn = false;  // live DMX input from a console drives the fixtures
  std::string bind = "127.0.0.1";
};

int fail(const std::string& line) {
  std::fprintf(stderr, "haze: %s\n", line.c_str());
  return 1;
}

// Everything the window shows of one show; replaced whole when another show is opened.
struct Stage {
  Show show;
  ProfileSet profiles;
  Venue venue;
};

Result<std::unique_ptr<Stage>> openStage(const std::string& file) {
  auto stage = std::make_unique<Stage>();
  auto show = loadShow(file);
  if (!show) return show.error();
  stage->show = std::move(*show);
  auto profiles = loadProfiles(stage->show);
  if (!profiles) return profiles.error();
  stage->profiles = std::move(*profiles);
  auto venue = loadVenue(stage->show.resolve(stage->show.venueGltf));
  if (!venue) return venue.error();
  stage->venue = std::move(*venue);
  return stage;
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

}  // namespace

int runGui(const Args& args) {
  Options opt;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto intValue = [&](int& dst) {
      if (i + 1 >= args.size()) return false;
      const std::string& s = args[++i];
      return std::from_chars(s.data(), s.data() + s.size(), dst).ec == std::errc() && dst > 0;
    };
    if (a == "--screenshot" && i + 1 < args.size()) opt.screenshot = args[++i];
    else if (a == "--artnet") opt.artNet = true;
    else if (a == "--sacn") opt.sacn = true;
    else if (a == "--bind" && i + 1 < args.size()) opt.bind = args[++i];
    else if (a == "--frames") { if (!intValue(opt.frames)) return fail("--frames needs a positive number"); }
    else if (a == "--width") { if (!intValue(opt.width)) return fail("--width needs a positive number"); }
    else if (a == "--height") { if (!intValue(opt.height)) return fail("--height needs a positive number"); }
    else if (!a.empty() && a[0] == '-') return fail("open: unknown option '" + a + "'");
    else opt.show = a;
  }
  if (opt.show.empty()) opt.show = HAZE_DEMO_SHOW;
  if (!opt.screenshot.empty() && opt.frames <= 0) opt.frames = 3;

  auto opened = openStage(opt.show);
  if (!opened) return fail(opened.error().str());
  std::unique_ptr<Stage> stage = std::move(*opened);
  std::unique_ptr<LiveReceiver> live;
  if (opt.artNet || opt.sacn) {
    LiveOptions lo;
    lo.udp.bindAddress = opt.bind;
    lo.udp.artNet = opt.artNet;
    lo.udp.sacn = opt.sacn;
    auto r = LiveReceiver::open(stage->show, stage->profiles, lo);
    if (!r) return fail(r.error().str());
    live = std::move(*r);
  }

#ifdef NDEBUG
  const bool debugGl = std::getenv("HAZE_GL_DEBUG") != nullptr;
#else
  const bool debugGl = true;  // debug builds always report GL errors (KHR_debug)
#endif
  auto ctx = WindowContext::create(opt.width, opt.height, "haze - " + stage->show.file.filename().string(), debugGl);
  if (!ctx) return fail(ctx.error().str());
  GLFWwindow* window = (*ctx)->window();

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is ours, not a file in the working folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");

  // Two renderers on one window: draft while anything moves (a drag, a fade), so the view keeps
  // up; default when still, refining progressively (more jittered frames each redraw).
  std::unique_ptr<Renderer> draft, still;
  int rendererW = 0, rendererH = 0;
  int stillFrames = 0;
  Orbit lastOrbit{};
  float lastScattering = -1.0f;
  const CueList* list = stage->show.findCueList("");
  size_t cue = 0;
  auto goTime = std::chrono::steady_clock::now();
  Orbit orbit = stage->show.cameras.empty() ? Orbit{} : Orbit::from(stage->show.cameras.front());
  std::string status;                 // the last file operation's outcome, one line
  char pathField[1024] = "";
  enum class FileAction { None, Open, ImportMvr, SaveAs } pending = FileAction::None, action = FileAction::None;
  // Swaps in another show (renderers are remade for its venue on the next frame).
  auto adopt = [&](std::unique_ptr<Stage> next) {
    stage = std::move(next);
    list = stage->show.findCueList("");
    cue = 0;
    goTime = std::chrono::steady_clock::now();
    orbit = stage->show.cameras.empty() ? Orbit{} : Orbit::from(stage->show.cameras.front());
    draft.reset();
    still.reset();
    live.reset();  // live input was bound to the old show's patch
    glfwSetWindowTitle(window, ("haze - " + stage->show.file.filename().string()).c_str());
  };
  float exposureEv = 0.0f;
  double frameMs = 0.0;
  int frame = 0;
  int exitCode = 0;

  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    int fbW = 0, fbH = 0;
    glfwGetFramebufferSize(window, &fbW, &fbH);
    if (fbW <= 0 || fbH <= 0) continue;
    if (!still || fbW != rendererW || fbH != rendererH) {
      auto d = Renderer::create(stage->venue, renderSettingsFor(Quality::Draft, fbW, fbH));
      if (!d) { exitCode = fail(d.error().str()); break; }
      auto s = Renderer::create(stage->venue, renderSettingsFor(Quality::Default, fbW, fbH));
      if (!s) { exitCode = fail(s.error().str()); break; }
      draft = std::move(*d);
      still = std::move(*s);
      rendererW = fbW;
      rendererH = fbH;
      stillFrames = 0;
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    const bool hasList = list && !list->cues.empty();
    auto go = [&](size_t to) {
      cue = to;
      goTime = std::chrono::steady_clock::now();
    };
    // ImGui 1.86's IsKeyPressed takes the backend's key codes: GetKeyIndex maps named keys to them.
    auto pressed = [](ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key)); };
    if (!io.WantCaptureKeyboard && hasList) {
      if ((pressed(ImGuiKey_Space) || pressed(ImGuiKey_Enter)) && cue + 1 < list->cues.size()) go(cue + 1);
      if (pressed(ImGuiKey_Backspace) && cue > 0) go(cue - 1);
    }
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Q)) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (!io.WantCaptureMouse) {
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        orbit.yawRad -= io.MouseDelta.x * 0.005f;
        orbit.pitchRad = std::clamp(orbit.pitchRad + io.MouseDelta.y * 0.005f, -1.5f, 1.5f);
      }
      if (io.MouseWheel != 0.0f) orbit.distanceM = std::clamp(orbit.distanceM * std::pow(0.9f, io.MouseWheel), 0.5f, 200.0f);
    }

    if (ImGui::BeginMainMenuBar()) {
      if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open show...")) pending = FileAction::Open;
        if (ImGui::MenuItem("Import MVR...")) pending = FileAction::ImportMvr;
        if (ImGui::MenuItem("Save", "Ctrl+S")) {
          const Status st = saveShow(stage->show, stage->show.file);
          status = st ? "saved " + stage->show.file.string() : st.error().str();
        }
        if (ImGui::MenuItem("Save as...")) pending = FileAction::SaveAs;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) glfwSetWindowShouldClose(window, GLFW_TRUE);
        ImGui::EndMenu();
      }
      if (!status.empty()) ImGui::TextUnformatted(status.c_str());
      ImGui::EndMainMenuBar();
    }
    if (pending != FileAction::None) {
      ImGui::OpenPopup("File");
      pathField[0] = '\0';
    }
    if (pending != FileAction::None) action = pending;
    pending = FileAction::None;
    if (ImGui::BeginPopupModal("File", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
      ImGui::TextUnformatted(action == FileAction::Open ? "Open show (.haze.json):"
                             : action == FileAction::ImportMvr ? "Import MVR (.mvr); the show is written beside it:"
                                                               : "Save show as (.haze.json):");
      ImGui::InputText("##path", pathField, sizeof(pathField));
      if (ImGui::Button("OK")) {
        const std::string path = pathField;
        if (action == FileAction::Open) {
          auto next = openStage(path);
          status = next ? "opened " + path : next.error().str();
          if (next) adopt(std::move(*next));
        } else if (action == FileAction::ImportMvr) {
          const std::filesystem::path showFile = std::filesystem::path(path).replace_extension(".haze.json");
          auto imported = importMvr(path, showFile);
          if (!imported) {
            status = imported.error().str();
          } else {
            auto next = openStage(showFile.string());
            status = next ? "imported " + showFile.string() : next.error().str();
            if (next) adopt(std::move(*next));
          }
        } else if (action == FileAction::SaveAs) {
          const Status st = saveShow(stage->show, path);
          status = st ? "saved " + path : st.error().str();
        }
        ImGui::CloseCurrentPopup();
      }
      ImGui::SameLine();
      if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
      ImGui::EndPopup();
    }
    if (!io.WantCaptureKeyboard && io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S)) {
      const Status st = saveShow(stage->show, stage->show.file);
      status = st ? "saved " + stage->show.file.string() : st.error().str();
    }

    ImGui::SetNextWindowPos(ImVec2(10, 30), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(300, 360), ImGuiCond_FirstUseEver);
    ImGui::Begin("Playback");
    // One line whatever the state, so the controls below never move under the pointer.
    if (stillFrames > 0) ImGui::Text("%.0f ms per frame, refining: %d frames", frameMs, stillFrames);
    else ImGui::Text("%.0f ms per frame, draft", frameMs);
    if (hasList) {
      ImGui::Text("List: %s", list->name.c_str());
      if (ImGui::Button("GO") && cue + 1 < list->cues.size()) go(cue + 1);
      ImGui::SameLine();
      if (ImGui::Button("BACK") && cue > 0) go(cue - 1);
      for (size_t i = 0; i < list->cues.size(); ++i) {
        const Cue& c = list->cues[i];
        const std::string label = c.number + "  " + c.label;
        if (ImGui::Selectable(label.c_str(), i == cue)) go(i);
      }
    }
    if (live) {
      ImGui::Separator();
      ImGui::Text("Live DMX on %s: %.0f packets/s", opt.bind.c_str(), live->packetRate());
      const auto sources = live->sources();
      if (sources.empty()) ImGui::TextUnformatted("no source: holding the last levels");
      for (const DmxSourceInfo& src : sources)
        ImGui::Text("%s %s  universe %d  priority %d", src.winning ? "*" : " ", src.name.c_str(), src.universe,
                    src.priority);
      ImGui::Separator();
    }
    ImGui::SliderFloat("Haze (1/m)", &stage->show.atmosphere.scattering, 0.0f, 0.2f, "%.3f");
    ImGui::SliderFloat("Exposure (EV)", &exposureEv, -6.0f, 6.0f, "%.1f");
    ImGui::TextUnformatted("Drag: orbit. Wheel: zoom. Space/Enter: GO.\nBackspace: BACK. Ctrl+S: save. Ctrl+Q: quit.");
    ImGui::End();
    ImGui::Render();

    const auto t0 = std::chrono::steady_clock::now();
    const double sinceGo = std::chrono::duration<double>(t0 - goTime).count();
    // A console on the network drives the rig directly; otherwise the cue list does.
    StageState state = live ? live->poll(0)
                       : hasList ? stateAt(stage->show, stage->profiles, *list, cue, sinceGo)
                                 : StageState{};
    auto frameState = buildFrame(stage->show, stage->profiles, state, "");
    if (!frameState) { exitCode = fail(frameState.error().str()); break; }
    frameState->camera.position = orbit.position();
    frameState->camera.target = orbit.target;
    const Cue* current = hasList ? &list->cues[cue] : nullptr;
    const bool fading = live || (current && sinceGo < current->delayS + current->fadeS);
    const bool moved = orbit.position() != lastOrbit.position() || orbit.target != lastOrbit.target ||
                       stage->show.atmosphere.scattering != lastScattering;
    lastOrbit = orbit;
    lastScattering = stage->show.atmosphere.scattering;
    Renderer* r = nullptr;
    if (fading || moved) {
      r = draft.get();
      r->render(*frameState);
      stillFrames = 0;
    } else {
      r = still.get();
      r->render(*frameState, stillFrames > 0);  // keep adding jittered frames while still
      ++stillFrames;
    }
    r->drawDisplay({.exposureEv = exposureEv}, 0, 0, 0, fbW, fbH);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    ++frame;
    if (opt.frames > 0 && frame >= opt.frames) {
      if (!opt.screenshot.empty()) {
        const Status s = saveScreenshot(fbW, fbH, opt.screenshot);
        if (!s) exitCode = fail(s.error().str());
      }
      glfwSwapBuffers(window);
      break;
    }
    glfwSwapBuffers(window);
  }

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return exitCode;
}

}  // namespace haze
