// A video rendered on a Slurm cluster (docs/output.md, "Rendering on a cluster"): the frames cut
// into chunks, one task of a job array per chunk, each running `haze render --frames A-B
// --resume` into a folder every node shares, then one job that waits for the array
// (--dependency=afterok) and encodes the frames into the video with `haze farm encode`. This file
// plans the chunks and writes the scripts; `haze farm` (app/cmd_farm.cpp) runs sbatch. Pure, so
// the scripts are tested as text.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/frame/frame_sequence.h"

namespace haze {

// Frames 0..frames-1 cut into runs of `chunk` (the last may be shorter); chunk i is task i.
std::vector<FrameRange> planChunks(int frames, int chunk);
// The chunks that hold at least one of `missing` (frame numbers), in order: the array tasks a
// resubmission needs.
std::vector<int> chunksWithFrames(const std::vector<FrameRange>& chunks, const std::vector<int>& missing);
// Task ids as sbatch's --array takes them: {0,1,2,5} -> "0-2,5".
std::string arraySpec(const std::vector<int>& tasks);
// `text` as one word for bash, in single quotes where it needs them.
std::string shellQuote(const std::string& text);

// What the farm folder's farm.json records, so that `haze farm status` and `haze farm encode`
// need only the folder.
struct FarmManifest {
  std::string show;      // absolute path of the show
  std::string video;     // absolute path of the video the encode job writes
  std::string pattern = "frame-%05d.png";  // the frames' names inside the folder
  std::string title;     // the video's title tag ("demo.haze.json, cue list Main")
  int frames = 0;
  int chunk = 0;
  int fps = 25;
  int width = 0, height = 0;
};

std::string manifestJson(const FarmManifest& manifest);
// Errors name the file and the JSON pointer.
Result<FarmManifest> readManifest(const std::filesystem::path& file);

struct SlurmJob {
  FarmManifest manifest;
  std::filesystem::path haze;    // the program as every node runs it (absolute, or a name on PATH)
  std::filesystem::path folder;  // the shared output folder (absolute)
  std::vector<std::string> renderArgs;  // the rest of `haze render`'s options (size, quality, cues)
  std::vector<int> tasks;        // the array's tasks: chunk indices still to render
  std::string partition;         // "" : the cluster's default
  int cpusPerTask = 1;
};

struct SlurmScripts {
  std::string render;  // render.sbatch: the job array
  std::string encode;  // encode.sbatch: the encode, after the array
  std::string submit;  // submit.sh: sbatch both, the second depending on the first
};

SlurmScripts slurmScripts(const SlurmJob& job);

}  // namespace haze
