// Video files through FFmpeg's libraries (libavformat, libavcodec, libswscale): 8-bit sRGB frames
// in, H.264 in MP4 by default (libx264), at a fixed quality. The file is written under a
// temporary name beside the target and renamed by finish(), so a failed or interrupted encode
// never leaves a file under the final name.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "fixtures/core/result.h"

namespace haze {

struct VideoOptions {
  int width = 0;
  int height = 0;
  int fps = 25;
  std::string codec = "libx264";  // an FFmpeg encoder name
  // libx264's constant rate factor: 18 looks like the source to most eyes (docs/rendering.md).
  int crf = 18;
  std::string title;  // the container's title tag
};

class VideoWriter {
 public:
  // The container comes from the file's extension (.mp4, .mkv, .mov, ...). Errors name the file
  // and the step: no such encoder, the container refuses the codec, the folder is not writable.
  static Result<std::unique_ptr<VideoWriter>> create(const std::filesystem::path& file, const VideoOptions& options);
  ~VideoWriter();  // without finish(): the temporary file is removed

  // One frame, width x height x 3 bytes of sRGB, row 0 at the top.
  Status addFrame(std::span<const unsigned char> rgb8);
  // Flushes the encoder, writes the trailer and renames the temporary file onto the target.
  Status finish();
  int frames() const;

 private:
  struct Impl;
  explicit VideoWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace haze
