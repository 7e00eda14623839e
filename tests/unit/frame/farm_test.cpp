// Rendering on a cluster, the pure parts: --frames ranges, image-sequence names, the scan for
// missing frames, chunk planning, and the Slurm scripts as text (the array, the dependency, the
// encode step); tests/cli/render_frames.sh renders with them and tools/farm_test.sh runs Slurm.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

#include "shows/frame/frame_sequence.h"
#include "shows/frame/slurm_job.h"

namespace haze {
namespace {

TEST(FrameRange, ParsesARangeOrOneFrame) {
  EXPECT_EQ(*parseFrameRange("0-49"), (FrameRange{0, 49}));
  EXPECT_EQ(*parseFrameRange("7"), (FrameRange{7, 7}));
  EXPECT_EQ(parseFrameRange("120-299")->count(), 180);
}

TEST(FrameRange, RefusesWhatIsNotARange) {
  for (const char* bad : {"", "-", "3-", "-3", "a-b", "1-2-3", "5-4", " 1-2", "1.5-2", "+1-2", "99999999999"}) {
    auto r = parseFrameRange(bad);
    ASSERT_FALSE(r) << bad;
    EXPECT_EQ(r.error().message.rfind("--frames: ", 0), 0u) << r.error().message;
  }
}

TEST(FrameSequence, NamesFramesByThePattern) {
  std::string error;
  EXPECT_TRUE(isImageSequence("out/frame-%05d.png", error));
  EXPECT_TRUE(error.empty());
  EXPECT_EQ(sequenceFile("out/frame-%05d.png", 42), std::filesystem::path("out/frame-00042.png"));
  EXPECT_EQ(sequenceFile("f%d.exr", 3), std::filesystem::path("f3.exr"));
  EXPECT_FALSE(isImageSequence("video.mp4", error));
  EXPECT_TRUE(isImageSequence("a-%d-%d.png", error));
  EXPECT_FALSE(error.empty());
}

TEST(FrameSequence, MissingFramesAreTheOnesTheCheckRefuses) {
  const std::set<std::string> present = {"f-00000.png", "f-00001.png", "f-00003.png", "f-00006.png"};
  const auto complete = [&](const std::filesystem::path& p) { return present.contains(p.filename().string()); };
  const std::vector<int> missing = missingFrames("dir/f-%05d.png", 8, complete);
  EXPECT_EQ(missing, (std::vector<int>{2, 4, 5, 7}));
  EXPECT_EQ(framesText(missing), "2, 4-5, 7");
  EXPECT_EQ(framesText({0, 1, 2, 7, 9, 10}), "0-2, 7, 9-10");
  EXPECT_EQ(framesText({}), "");
}

TEST(Chunks, CoverEveryFrameOnceWithAShortLastChunk) {
  const auto chunks = planChunks(103, 25);
  ASSERT_EQ(chunks.size(), 5u);
  EXPECT_EQ(chunks[0], (FrameRange{0, 24}));
  EXPECT_EQ(chunks[4], (FrameRange{100, 102}));
  int next = 0;
  for (const FrameRange& c : chunks) {
    EXPECT_EQ(c.first, next);
    next = c.last + 1;
  }
  EXPECT_EQ(next, 103);
  EXPECT_EQ(planChunks(50, 50).size(), 1u);
}

TEST(Chunks, AResubmissionRunsOnlyTheChunksWithMissingFrames) {
  const auto chunks = planChunks(100, 10);
  EXPECT_EQ(chunksWithFrames(chunks, {13, 14, 55, 99}), (std::vector<int>{1, 5, 9}));
  EXPECT_TRUE(chunksWithFrames(chunks, {}).empty());
  EXPECT_EQ(arraySpec({0, 1, 2, 3, 7, 9, 10}), "0-3,7,9-10");
}

TEST(ShellQuote, QuotesOnlyWhatBashWouldSplitOrExpand) {
  EXPECT_EQ(shellQuote("/srv/show/demo.haze.json"), "/srv/show/demo.haze.json");
  EXPECT_EQ(shellQuote("my show.json"), "'my show.json'");
  EXPECT_EQ(shellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(shellQuote("$HOME"), "'$HOME'");
  EXPECT_EQ(shellQuote(""), "''");
}

SlurmJob demoJob() {
  SlurmJob job;
  job.manifest = {.show = "/shared/show/demo.haze.json", .video = "/shared/out/demo.mp4",
                  .title = "demo.haze.json, cue list Main", .frames = 230, .chunk = 50, .fps = 25,
                  .width = 1280, .height = 720};
  job.haze = "/opt/haze/bin/haze";
  job.folder = "/shared/out/demo.frames";
  job.renderArgs = {"--quality", "high", "--width", "1280", "--height", "720", "--fps", "25"};
  job.tasks = {0, 1, 2, 3, 4};
  job.partition = "render";
  return job;
}

TEST(SlurmScripts, TheRenderArrayRunsOneChunkPerTask) {
  const SlurmScripts s = slurmScripts(demoJob());
  EXPECT_NE(s.render.find("#SBATCH --array=0-4\n"), std::string::npos) << s.render;
  EXPECT_NE(s.render.find("#SBATCH --partition=render\n"), std::string::npos);
  EXPECT_NE(s.render.find("#SBATCH --output=/shared/out/demo.frames/logs/render-%A_%a.log\n"), std::string::npos);
  EXPECT_NE(s.render.find("chunk=50\nframes=230\n"), std::string::npos);
  EXPECT_NE(s.render.find("first=$((SLURM_ARRAY_TASK_ID * chunk))"), std::string::npos);
  EXPECT_NE(s.render.find("\"$haze\" render \"$show\" --video \"$folder/frame-%05d.png\" --frames \"$first-$last\" "
                          "--resume --quality high --width 1280 --height 720 --fps 25\n"),
            std::string::npos)
      << s.render;
  EXPECT_NE(s.render.find("haze=/opt/haze/bin/haze\n"), std::string::npos);
}

TEST(SlurmScripts, TheEncodeWaitsForTheWholeArray) {
  const SlurmScripts s = slurmScripts(demoJob());
  EXPECT_NE(s.encode.find("\"$haze\" farm encode /shared/out/demo.frames\n"), std::string::npos) << s.encode;
  EXPECT_NE(s.encode.find("#SBATCH --job-name=haze-encode"), std::string::npos);
  EXPECT_NE(s.submit.find("render=$(sbatch --parsable /shared/out/demo.frames/render.sbatch)"), std::string::npos)
      << s.submit;
  EXPECT_NE(s.submit.find("sbatch --parsable --dependency=afterok:$render /shared/out/demo.frames/encode.sbatch"),
            std::string::npos);
}

TEST(SlurmScripts, AResubmissionListsOnlyTheMissingChunksAndNoneWhenComplete) {
  SlurmJob job = demoJob();
  job.tasks = {1, 4};
  EXPECT_NE(slurmScripts(job).render.find("#SBATCH --array=1,4\n"), std::string::npos);
  job.tasks = {};
  const SlurmScripts s = slurmScripts(job);
  EXPECT_EQ(s.submit.find("render.sbatch"), std::string::npos) << s.submit;
  EXPECT_NE(s.submit.find("encode=$(sbatch --parsable /shared/out/demo.frames/encode.sbatch)"), std::string::npos);
}

// The scripts are bash that bash accepts (bash -n), paths with spaces and quotes included.
TEST(SlurmScripts, PassBashSyntaxCheck) {
  SlurmJob job = demoJob();
  job.manifest.show = "/shared/my show's/demo.haze.json";
  job.renderArgs.push_back("--list");
  job.renderArgs.push_back("Main $list");
  const SlurmScripts s = slurmScripts(job);
  const auto dir = std::filesystem::temp_directory_path() / ("haze_farm_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const auto& [name, text] : {std::pair{"render.sbatch", &s.render}, {"encode.sbatch", &s.encode},
                                   {"submit.sh", &s.submit}}) {
    const auto file = dir / name;
    std::ofstream(file) << *text;
    const std::string command = "bash -n '" + file.string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << name << ":\n" << *text;
  }
  EXPECT_NE(s.render.find("show='/shared/my show'\\''s/demo.haze.json'"), std::string::npos) << s.render;
  std::filesystem::remove_all(dir);
}

TEST(Manifest, RoundTripsAndNamesTheBadField) {
  const FarmManifest m = demoJob().manifest;
  const auto dir = std::filesystem::temp_directory_path() / ("haze_manifest_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "farm.json") << manifestJson(m);
  auto back = readManifest(dir / "farm.json");
  ASSERT_TRUE(back) << back.error().str();
  EXPECT_EQ(back->frames, 230);
  EXPECT_EQ(back->pattern, "frame-%05d.png");
  EXPECT_EQ(back->video, m.video);
  std::ofstream(dir / "bad.json") << R"({"show": "s", "video": "v", "pattern": "frame.png", "title": "",
      "frames": 3, "chunk": 1, "fps": 25, "width": 8, "height": 8})";
  auto bad = readManifest(dir / "bad.json");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().place, "/pattern");
  std::ofstream(dir / "bad2.json") << R"({"show": "s"})";
  EXPECT_EQ(readManifest(dir / "bad2.json").error().place, "/video");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace haze
