#pragma once
// The door of src/video: the FFmpeg side of bookspin, encoded and decoded in-process with
// FFmpeg's libraries (libavcodec, libavformat, libavfilter, libswscale). This stage alone
// links them; the headers below include none of theirs (libav_support.hpp and
// codec_selection.hpp, which do, are the stage's own business).
//
//   mp4_encoder.hpp    Mp4Encoder: RGBA frames → MP4, one H.264 yuv420p stream (libx264 or
//                      another H.264 encoder, falling back to libx264), and EncoderError
//   web_encoders.hpp   WebmEncoder (VP9) and GifEncoder (one palette over the whole clip,
//                      libavfilter's palettegen and paletteuse) from the same frames
//   video_quality.hpp  a video file decoded back to RGBA frames; SSIM and PSNR of a decoded
//                      frame against its original (bookspin-bench's choice of preset)
//   ffmpeg_info.hpp    what FFmpeg the program runs with and which H.264 encoders open
//                      (`bookspin info`)
//
// Units: sizes in pixels (even for 4:2:0 video), rates in frames per second, frame k of a clip
// at k/fps seconds; frames are RGBA, top row first (common/rgba_image.hpp); SSIM is 1 for
// identical images, PSNR in dB. Every file is written under a temporary name through
// output::AtomicFile and appears only when finish() succeeds, or when the output::OutputSet
// it was handed commits; an encoder destroyed before removes it.
//
// Errors: bad settings or a frame of the wrong size → std::invalid_argument; libav refusing
// (an encoder missing or failing, a file it cannot decode) → EncoderError; the file system →
// OutputError naming the path; a StopPoll answering a signal while an encoder finishes →
// Interrupted (nothing put in place).
#include "video/ffmpeg_info.hpp"
#include "video/mp4_encoder.hpp"
#include "video/video_quality.hpp"
#include "video/web_encoders.hpp"
