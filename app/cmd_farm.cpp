// haze farm slurm SHOW --video OUT.mp4 [--chunk N] [--quality Q] [--partition P] [--submit] ...
// haze farm status FOLDER
// haze farm encode FOLDER
// A show's video rendered on a Slurm cluster (docs/output.md, "Rendering on a cluster"): the plan
// and the scripts are shows/frame/slurm_job.h's; this wires them to the show, the folder and sbatch.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/command_line.h"
#include "app/commands.h"
#include "fixtures/core/atomic_file.h"
#include "renderer/output/frame_files.h"
#include "renderer/output/video_writer.h"
#include "shows/frame/frame_sequence.h"
#include "shows/frame/slurm_job.h"
#include "shows/frame/video_timeline.h"
#include "shows/playback.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze farm slurm SHOW --video OUT.mp4 [--chunk N] [--quality draft|default|high|reference]\n"
    "                  [--partition P] [--cpus N] [--folder DIR] [--haze PATH] [--submit]\n"
    "                  [--list NAME] [--from CUE] [--to CUE] [--fps N] [--hold S] [--duration S]\n"
    "                  [--width W --height H] [--camera NAME]\n"
    "       haze farm status FOLDER\n"
    "       haze farm encode FOLDER [--codec NAME]\n"
    "slurm writes a Slurm job array into FOLDER (default: OUT without its extension, plus .frames/):\n"
    "render.sbatch (one task per --chunk frames, default 50, each `haze render --frames A-B --resume`\n"
    "into FOLDER/frame-%05d.png), encode.sbatch (after the whole array succeeded: `haze farm encode`)\n"
    "and submit.sh, which --submit runs (sbatch). Run it again after a failure: the array then holds\n"
    "only the chunks with frames missing. FOLDER, the show and the files it names must be on a\n"
    "filesystem every node shares; --haze PATH is the program as the nodes run it (default: this one).\n"
    "--cpus N: CPUs per task (llvmpipe's threads). status says which frames are missing or cut short.\n"
    "encode checks that every frame is complete and encodes them as --video does (H.264, CRF 18).\n";

std::filesystem::path absolute(const std::string& path) {
  std::error_code ec;
  const auto a = std::filesystem::absolute(path, ec);
  return (ec ? std::filesystem::path(path) : a).lexically_normal();
}

// Seconds as the command line would give them ("2", "12.5"), not std::to_string's "2.000000",
// with as many digits as the same double needs when the task reads it back.
std::string secondsText(double s) {
  char text[32];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, s);
    if (std::strtod(text, nullptr) == s) break;
  }
  return text;
}

std::filesystem::path thisProgram() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path("haze") : exe;
}

int runSlurm(const Args& args) {
  std::string showPath, video, quality = "default", partition, folderText, hazePath, list, from, to, camera;
  int chunk = 50, cpus = 1, fps = 25, width = 1280, height = 720;
  double hold = 2.0, duration = 0.0;
  bool submit = false;
  CommandLine cli("haze farm slurm", kUsage);
  cli.text("--video", video, "the video to make (OUT.mp4)")
      .integer("--chunk", chunk, 1, 1000000, "frames per task, a whole number >= 1")
      .choice("--quality", quality, {"draft", "default", "high", "reference"})
      .text("--partition", partition, "a Slurm partition")
      .integer("--cpus", cpus, 1, 1024, "CPUs per task, 1..1024")
      .text("--folder", folderText, "the shared folder for the frames")
      .text("--haze", hazePath, "the haze program as the nodes run it")
      .flag("--submit", submit)
      .text("--list", list, "a cue list name")
      .text("--from", from, "a cue number")
      .text("--to", to, "a cue number")
      .integer("--fps", fps, 1, 240, "frames per second, 1..240")
      .number("--hold", hold, 0, 3600, "seconds 0..3600")
      .number("--duration", duration, 0, 86400, "seconds 0..86400")
      .integer("--width", width, 1, 16384, "a whole number 1..16384")
      .integer("--height", height, 1, 16384, "a whole number 1..16384")
      .text("--camera", camera, "a camera name")
      .positional(showPath, "show");
  if (auto done = cli.parse(args)) return *done;
  std::string patternError;
  if (video.empty()) return cli.usage("--video OUT.mp4 names the video the farm makes");
  if (isImageSequence(video, patternError))
    return cli.usage("--video names the video file (OUT.mp4); the frames go to the farm's folder");
  if (partition.find_first_of(" \t\n'\"$\\") != std::string::npos)
    return cli.usage("--partition: expected a Slurm partition name, got '" + partition + "'");

  auto checked = cli.readShow(showPath);
  if (!checked) return kExitBadInput;
  const Show& show = checked->show;
  const CueList* cueList = show.findCueList(list);
  if (!cueList) return cli.fail(showPath + ": no cue list" + (list.empty() ? "" : " named '" + list + "'"));
  if (cueList->cues.empty()) return cli.fail(showPath + ": cue list '" + cueList->name + "' has no cues");
  // The frame count is the timeline's, played here exactly as every task and `haze render --video`
  // play it (no drawing).
  VideoPlan plan{.list = cueList, .from = 0, .to = cueList->cues.size() - 1, .holdS = hold, .durationS = duration,
                 .fps = fps};
  for (auto [number, index] : {std::pair{&from, &plan.from}, std::pair{&to, &plan.to}}) {
    if (number->empty()) continue;
    auto found = findCue(*cueList, *number);
    if (!found) return cli.fail(showPath + ": " + found.error().message);
    *index = *found;
  }
  if (plan.from > plan.to) return cli.fail("--from " + from + " comes after --to " + to);
  const int frames = VideoTimeline(show, checked->profiles, plan).frames();

  const auto videoPath = absolute(video);
  const auto folder = folderText.empty() ? absolute(videoPath.parent_path() / (videoPath.stem().string() + ".frames"))
                                         : absolute(folderText);
  // sbatch's #SBATCH --output takes the path unquoted.
  if (folder.string().find_first_of(" \t\n") != std::string::npos)
    return cli.usage("--folder: a folder whose path has no spaces (Slurm's --output line takes it bare), got '" +
                     folder.string() + "'");
  std::error_code ec;
  std::filesystem::create_directories(folder / "logs", ec);
  if (ec) return cli.fail(folder.string() + ": cannot create the farm's folder: " + ec.message());

  SlurmJob job;
  job.manifest = {.show = absolute(showPath).string(), .video = videoPath.string(),
                  .title = show.file.filename().string() + ", cue list " + cueList->name, .frames = frames,
                  .chunk = chunk, .fps = fps, .width = width, .height = height};
  job.haze = hazePath.empty() ? thisProgram() : std::filesystem::path(hazePath);
  job.folder = folder;
  job.renderArgs = {"--list", cueList->name, "--from", cueList->cues[plan.from].number, "--to",
                    cueList->cues[plan.to].number, "--fps", std::to_string(fps), "--hold", secondsText(hold),
                    "--width", std::to_string(width), "--height", std::to_string(height), "--quality", quality};
  if (duration > 0) job.renderArgs.insert(job.renderArgs.end(), {"--duration", secondsText(duration)});
  if (!camera.empty()) job.renderArgs.insert(job.renderArgs.end(), {"--camera", camera});
  job.partition = partition;
  job.cpusPerTask = cpus;
  const auto chunks = planChunks(frames, chunk);
  const std::vector<int> missing = missingFrames(folder / job.manifest.pattern, frames, frameFileComplete);
  job.tasks = chunksWithFrames(chunks, missing);

  const SlurmScripts scripts = slurmScripts(job);
  for (const auto& [name, text] : {std::pair{"farm.json", manifestJson(job.manifest)},
                                   {"render.sbatch", scripts.render}, {"encode.sbatch", scripts.encode},
                                   {"submit.sh", scripts.submit}})
    if (Status s = writeFileAtomically(folder / name, text, false); !s) return cli.fail(s.error().str());
  std::printf("%s: %d frames at %d fps in %zu chunks of %d; to render: %zu frames in %zu tasks (array %s)\n",
              folder.string().c_str(), frames, fps, chunks.size(), chunk, missing.size(), job.tasks.size(),
              job.tasks.empty() ? "none" : arraySpec(job.tasks).c_str());
  if (!submit) {
    std::printf("submit with: bash %s\n", shellQuote((folder / "submit.sh").string()).c_str());
    return 0;
  }
  std::fflush(stdout);
  const std::string command = "bash " + shellQuote((folder / "submit.sh").string());
  const int status = std::system(command.c_str());
  if (status != 0) return cli.fail((folder / "submit.sh").string() + ": sbatch failed (is Slurm's sbatch on PATH?)");
  return 0;
}

int runStatus(const Args& args) {
  std::string folderText;
  CommandLine cli("haze farm status", kUsage);
  cli.positional(folderText, "folder");
  if (auto done = cli.parse(args)) return *done;
  const std::filesystem::path folder(folderText);
  auto manifest = readManifest(folder / "farm.json");
  if (!manifest) return cli.fail(manifest.error().str());
  const std::vector<int> missing = missingFrames(folder / manifest->pattern, manifest->frames, frameFileComplete);
  std::printf("%s: %d of %d frames complete\n", folder.string().c_str(),
              manifest->frames - static_cast<int>(missing.size()), manifest->frames);
  if (missing.empty()) {
    std::printf("every frame is there: encode with haze farm encode %s\n", folder.string().c_str());
    return 0;
  }
  const auto chunks = planChunks(manifest->frames, manifest->chunk);
  std::printf("missing: %s (tasks %s); haze farm slurm again renders only these\n", framesText(missing).c_str(),
              arraySpec(chunksWithFrames(chunks, missing)).c_str());
  return 0;
}

int runEncode(const Args& args) {
  std::string folderText, codec = "libx264";
  CommandLine cli("haze farm encode", kUsage);
  cli.text("--codec", codec, "an FFmpeg encoder name").positional(folderText, "folder");
  if (auto done = cli.parse(args)) return *done;
  const std::filesystem::path folder(folderText);
  auto manifest = readManifest(folder / "farm.json");
  if (!manifest) return cli.fail(manifest.error().str());
  const auto pattern = folder / manifest->pattern;
  const std::vector<int> missing = missingFrames(pattern, manifest->frames, frameFileComplete);
  if (!missing.empty())
    return cli.fail(folder.string() + ": " + std::to_string(missing.size()) + " of " +
                    std::to_string(manifest->frames) + " frames missing or cut short: " + framesText(missing) +
                    " (haze farm slurm again renders only these)");
  auto writer = VideoWriter::create(manifest->video, {.width = manifest->width, .height = manifest->height,
                                                      .fps = manifest->fps, .codec = codec, .title = manifest->title});
  if (!writer) return cli.fail(writer.error().str());
  for (int f = 0; f < manifest->frames; ++f) {
    auto image = readPngRgb8(sequenceFile(pattern, f));
    if (!image) return cli.fail(image.error().str());
    if (image->width != manifest->width || image->height != manifest->height)
      return cli.fail(sequenceFile(pattern, f).string() + ": " + std::to_string(image->width) + "x" +
                      std::to_string(image->height) + ", not the farm's " + std::to_string(manifest->width) + "x" +
                      std::to_string(manifest->height));
    if (Status s = (*writer)->addFrame(image->rgb); !s) return cli.fail(s.error().str());
  }
  if (Status s = (*writer)->finish(); !s) return cli.fail(s.error().str());
  std::printf("%s: %d frames encoded from %s\n", manifest->video.c_str(), manifest->frames, folder.string().c_str());
  return 0;
}

}  // namespace

int runFarm(const Args& args) {
  const std::string what = args.empty() ? "" : args[0];
  const Args rest = args.empty() ? Args{} : Args(args.begin() + 1, args.end());
  if (what == "slurm") return runSlurm(rest);
  if (what == "status") return runStatus(rest);
  if (what == "encode") return runEncode(rest);
  if (what == "--help" || what == "-h") {
    std::fputs(kUsage, stdout);
    return kExitOk;
  }
  std::fprintf(stderr, "haze farm: expected slurm, status or encode%s\n%s",
               what.empty() ? "" : (", not '" + what + "'").c_str(), kUsage);
  return kExitUsage;
}

}  // namespace haze
