#include "shows/frame/slurm_job.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

namespace haze {

std::vector<FrameRange> planChunks(int frames, int chunk) {
  std::vector<FrameRange> chunks;
  for (int first = 0; first < frames; first += chunk) chunks.push_back({first, std::min(first + chunk, frames) - 1});
  return chunks;
}

std::vector<int> chunksWithFrames(const std::vector<FrameRange>& chunks, const std::vector<int>& missing) {
  std::vector<int> tasks;
  for (size_t i = 0; i < chunks.size(); ++i)
    if (std::any_of(missing.begin(), missing.end(),
                    [&](int f) { return f >= chunks[i].first && f <= chunks[i].last; }))
      tasks.push_back(static_cast<int>(i));
  return tasks;
}

std::string arraySpec(const std::vector<int>& tasks) {
  // framesText's runs, in sbatch's spelling (no spaces).
  std::string text = framesText(tasks);
  text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
  return text;
}

std::string shellQuote(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("/._-+=:,@").find(c) != std::string_view::npos;
  });
  if (plain) return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string manifestJson(const FarmManifest& m) {
  const nlohmann::json doc = {{"show", m.show},     {"video", m.video}, {"pattern", m.pattern},
                              {"title", m.title},   {"frames", m.frames}, {"chunk", m.chunk},
                              {"fps", m.fps},       {"width", m.width}, {"height", m.height}};
  return doc.dump(2) + "\n";
}

Result<FarmManifest> readManifest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{file.string(), "", "cannot open the farm's manifest (is this a folder `haze farm slurm` made?)"};
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return Error{file.string(), "", "not a JSON object"};
  FarmManifest m;
  for (auto [key, field] : {std::pair{"show", &m.show}, {"video", &m.video}, {"pattern", &m.pattern}, {"title", &m.title}}) {
    if (!doc.contains(key) || !doc[key].is_string()) return Error{file.string(), std::string("/") + key, "expected text"};
    *field = doc[key].get<std::string>();
  }
  for (auto [key, field] : {std::pair{"frames", &m.frames}, {"chunk", &m.chunk}, {"fps", &m.fps}, {"width", &m.width},
                            {"height", &m.height}}) {
    if (!doc.contains(key) || !doc[key].is_number_integer() || doc[key].get<int>() < 1)
      return Error{file.string(), std::string("/") + key, "expected a whole number >= 1"};
    *field = doc[key].get<int>();
  }
  std::string patternError;
  if (!isImageSequence(m.pattern, patternError) || !patternError.empty() || m.pattern.find('/') != std::string::npos)
    return Error{file.string(), "/pattern", "expected a frame file name with one frame number, like frame-%05d.png"};
  return m;
}

SlurmScripts slurmScripts(const SlurmJob& job) {
  const FarmManifest& m = job.manifest;
  const std::string folder = shellQuote(job.folder.string());
  const std::string logs = (job.folder / "logs").string();
  std::string args;
  for (const std::string& a : job.renderArgs) args += " " + shellQuote(a);
  const std::string head =
      "# Written by `haze farm slurm` (docs/output.md, \"Rendering on a cluster\"); run it again to\n"
      "# rewrite these scripts for the frames still missing.\n"
      "# Show:  " + m.show + "\n"
      "# Video: " + m.video + ", " + std::to_string(m.frames) + " frames at " + std::to_string(m.fps) +
      " fps, " + std::to_string(m.width) + "x" + std::to_string(m.height) + "\n"
      "# A node needs: the haze program below, the show and every file it names (venue, profiles,\n"
      "# gobos) at the same paths, and this folder, all on a filesystem every node shares. No\n"
      "# display and no GPU: haze renders headless through EGL, on Mesa's llvmpipe on the CPUs, or on\n"
      "# a GPU's EGL device where the node has one.\n";
  const std::string partition = job.partition.empty() ? "" : "#SBATCH --partition=" + job.partition + "\n";

  SlurmScripts s;
  s.render =
      "#!/bin/bash\n"
      "# haze render farm: one task of this job array renders one chunk of " + std::to_string(m.chunk) +
      " frames of the video\n"
      "# into the shared folder as PNGs. A frame already there and complete is skipped (--resume), and\n"
      "# each frame is written to a temporary name and renamed, so a task that dies leaves whole frames\n"
      "# only, and running a task again renders just the frames it lacks.\n" +
      head +
      "#SBATCH --job-name=haze-render\n"
      "#SBATCH --array=" + arraySpec(job.tasks) + "\n"
      "#SBATCH --cpus-per-task=" + std::to_string(job.cpusPerTask) + "\n" + partition +
      "#SBATCH --output=" + logs + "/render-%A_%a.log\n"
      "set -euo pipefail\n"
      "haze=" + shellQuote(job.haze.string()) + "\n"
      "show=" + shellQuote(m.show) + "\n"
      "folder=" + folder + "\n"
      "chunk=" + std::to_string(m.chunk) + "\n"
      "frames=" + std::to_string(m.frames) + "\n"
      "first=$((SLURM_ARRAY_TASK_ID * chunk))\n"
      "last=$((first + chunk - 1))\n"
      "if [ \"$last\" -ge \"$frames\" ]; then last=$((frames - 1)); fi\n"
      "# llvmpipe draws with as many threads as the CPUs Slurm gave this task, no more.\n"
      "export LP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n"
      "echo \"haze farm: task $SLURM_ARRAY_TASK_ID renders frames $first-$last on $(hostname)\"\n"
      "# Every task plays the whole timeline from frame 0 (cheap, no drawing) and draws only its\n"
      "# frames, with the exposure metered on the whole cue range: its frames are the ones a single\n"
      "# run would make, pixel for pixel.\n"
      "\"$haze\" render \"$show\" --video \"$folder/" + m.pattern + "\" --frames \"$first-$last\" --resume" + args + "\n";
  s.encode =
      "#!/bin/bash\n"
      "# haze render farm: after every task of the render array has succeeded, checks that every frame\n"
      "# is in the folder and complete, and encodes them into the video as `haze render --video` does\n"
      "# (FFmpeg, H.264 by libx264, CRF 18). A missing frame fails the job and names the frames;\n"
      "# `haze farm status` says the same, and `haze farm slurm` again renders only those.\n" +
      head +
      "#SBATCH --job-name=haze-encode\n"
      "#SBATCH --cpus-per-task=1\n" + partition +
      "#SBATCH --output=" + logs + "/encode-%j.log\n"
      "set -euo pipefail\n"
      "haze=" + shellQuote(job.haze.string()) + "\n"
      "\"$haze\" farm encode " + folder + "\n";
  const std::string encodeScript = shellQuote((job.folder / "encode.sbatch").string());
  s.submit =
      "#!/bin/bash\n"
      "# Submits the render array and the encode job that waits for it (--dependency=afterok: it runs\n"
      "# only if every task succeeded). Prints the two job ids.\n"
      "set -euo pipefail\n" +
      (job.tasks.empty()
           ? "# Every frame is there already: only the encode is left.\n"
             "encode=$(sbatch --parsable " + encodeScript + ")\n"
             "echo \"render: none (every frame is there)\"\n"
           : "render=$(sbatch --parsable " + shellQuote((job.folder / "render.sbatch").string()) + ")\n"
             "render=${render%%;*}\n"
             "encode=$(sbatch --parsable --dependency=afterok:$render " + encodeScript + ")\n"
             "echo \"render: job $render, array " + arraySpec(job.tasks) + "\"\n") +
      "encode=${encode%%;*}\n"
      "echo \"encode: job $encode\"\n";
  return s;
}

}  // namespace haze
