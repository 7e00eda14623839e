#include "renderer/output/video_writer.h"

#include <unistd.h>

#include <cstdio>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace haze {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

struct FormatDeleter {
  void operator()(AVFormatContext* f) const {
    if (f->pb) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};
struct CodecDeleter {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameDeleter {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketDeleter {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct ScaleDeleter {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};

}  // namespace

struct VideoWriter::Impl {
  std::filesystem::path file, tmp;
  VideoOptions options;
  std::unique_ptr<AVFormatContext, FormatDeleter> format;
  std::unique_ptr<AVCodecContext, CodecDeleter> codec;
  std::unique_ptr<AVFrame, FrameDeleter> frame;
  std::unique_ptr<AVPacket, PacketDeleter> packet;
  std::unique_ptr<SwsContext, ScaleDeleter> scale;
  AVStream* stream = nullptr;
  int64_t nextPts = 0;
  bool finished = false;

  Error error(const std::string& what) const { return Error{file.string(), "", what}; }

  // Sends one frame (nullptr: flush) and writes every packet the encoder has ready.
  Status encode(AVFrame* f) {
    int rc = avcodec_send_frame(codec.get(), f);
    if (rc < 0) return error("the encoder refused a frame: " + avError(rc));
    for (;;) {
      rc = avcodec_receive_packet(codec.get(), packet.get());
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return Ok{};
      if (rc < 0) return error("encoding failed: " + avError(rc));
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format.get(), packet.get());
      if (rc < 0) return error("cannot write the video (disk full?): " + avError(rc));
    }
  }

  void removeTemporary() {
    format.reset();  // closes the file
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
  }
};

VideoWriter::VideoWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

VideoWriter::~VideoWriter() {
  if (impl_ && !impl_->finished) impl_->removeTemporary();
}

int VideoWriter::frames() const { return static_cast<int>(impl_->nextPts); }

Result<std::unique_ptr<VideoWriter>> VideoWriter::create(const std::filesystem::path& file, const VideoOptions& options) {
  // Failures are reported as one line each by the caller; FFmpeg's own log would add more.
  av_log_set_level(AV_LOG_QUIET);
  auto impl = std::make_unique<Impl>();
  impl->file = file;
  impl->options = options;
  impl->tmp = file.parent_path() / ("." + file.filename().string() + ".tmp-" + std::to_string(getpid()));
  const auto fail = [&](const std::string& what) -> Error { return impl->error(what); };

  const AVOutputFormat* container = av_guess_format(nullptr, file.filename().string().c_str(), nullptr);
  if (!container) return fail("no video container for this extension (expected .mp4, .mkv or .mov)");
  const AVCodec* encoder = avcodec_find_encoder_by_name(options.codec.c_str());
  if (!encoder || encoder->type != AVMEDIA_TYPE_VIDEO)
    return fail("this FFmpeg has no video encoder '" + options.codec +
                "' (Debian's libavcodec has libx264; or write an image sequence, OUT-%05d.png)");
  if (options.width % 2 || options.height % 2)
    return fail("H.264 in 4:2:0 needs an even width and height (got " + std::to_string(options.width) + "x" +
                std::to_string(options.height) + ")");

  AVFormatContext* formatRaw = nullptr;
  int rc = avformat_alloc_output_context2(&formatRaw, container, nullptr, impl->tmp.string().c_str());
  if (rc < 0 || !formatRaw) return fail("cannot set up the container: " + avError(rc));
  impl->format.reset(formatRaw);
  impl->codec.reset(avcodec_alloc_context3(encoder));
  impl->frame.reset(av_frame_alloc());
  impl->packet.reset(av_packet_alloc());
  if (!impl->codec || !impl->frame || !impl->packet) return fail("out of memory setting up the encoder");

  AVCodecContext* c = impl->codec.get();
  c->width = options.width;
  c->height = options.height;
  c->time_base = AVRational{1, options.fps};
  c->framerate = AVRational{options.fps, 1};
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->gop_size = options.fps * 2;
  // The frames are sRGB; tag them so players convert back with the same matrix.
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_IEC61966_2_1;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  if (impl->format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (options.codec == "libx264") {
    av_opt_set(c->priv_data, "crf", std::to_string(options.crf).c_str(), 0);
    av_opt_set(c->priv_data, "preset", "medium", 0);
  }
  rc = avcodec_open2(c, encoder, nullptr);
  if (rc < 0) return fail("cannot open the encoder '" + options.codec + "': " + avError(rc));

  impl->stream = avformat_new_stream(impl->format.get(), nullptr);
  if (!impl->stream) return fail("cannot add a video stream");
  impl->stream->time_base = c->time_base;
  impl->stream->avg_frame_rate = c->framerate;
  rc = avcodec_parameters_from_context(impl->stream->codecpar, c);
  if (rc < 0) return fail("cannot describe the stream: " + avError(rc));
  if (!options.title.empty()) av_dict_set(&impl->format->metadata, "title", options.title.c_str(), 0);

  rc = avio_open(&impl->format->pb, impl->tmp.string().c_str(), AVIO_FLAG_WRITE);
  if (rc < 0) return fail("cannot create the file (does the folder exist, may it be written?): " + avError(rc));
  rc = avformat_write_header(impl->format.get(), nullptr);
  if (rc < 0) {
    impl->removeTemporary();
    return fail("the container refuses this stream (" + options.codec + "): " + avError(rc));
  }

  impl->frame->format = c->pix_fmt;
  impl->frame->width = c->width;
  impl->frame->height = c->height;
  rc = av_frame_get_buffer(impl->frame.get(), 0);
  if (rc < 0) {
    impl->removeTemporary();
    return fail("cannot allocate a frame: " + avError(rc));
  }
  impl->scale.reset(sws_getContext(c->width, c->height, AV_PIX_FMT_RGB24, c->width, c->height, c->pix_fmt,
                                   SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr));
  if (!impl->scale) {
    impl->removeTemporary();
    return fail("cannot set up the RGB to YUV conversion");
  }
  // BT.709 coefficients, limited range, as tagged above (swscale's default would be BT.601).
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(impl->scale.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  return std::unique_ptr<VideoWriter>(new VideoWriter(std::move(impl)));
}

Status VideoWriter::addFrame(std::span<const unsigned char> rgb8) {
  Impl& m = *impl_;
  if (rgb8.size() != static_cast<size_t>(m.options.width) * m.options.height * 3)
    return m.error("internal: frame buffer does not match the video's size");
  int rc = av_frame_make_writable(m.frame.get());
  if (rc < 0) return m.error("cannot reuse the frame: " + avError(rc));
  const uint8_t* src[1] = {rgb8.data()};
  const int srcStride[1] = {m.options.width * 3};
  sws_scale(m.scale.get(), src, srcStride, 0, m.options.height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.nextPts++;
  return m.encode(m.frame.get());
}

Status VideoWriter::finish() {
  Impl& m = *impl_;
  if (Status s = m.encode(nullptr); !s) return s;
  int rc = av_write_trailer(m.format.get());
  if (rc < 0) return m.error("cannot finish the video: " + avError(rc));
  rc = avio_closep(&m.format->pb);
  if (rc < 0) return m.error("cannot close the video (disk full?): " + avError(rc));
  std::error_code ec;
  std::filesystem::rename(m.tmp, m.file, ec);
  if (ec) return m.error("cannot move the finished video into place: " + ec.message());
  m.finished = true;
  return Ok{};
}

}  // namespace haze
