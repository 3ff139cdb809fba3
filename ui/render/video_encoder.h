// Where animation frames go: a folder of PNGs, an MP4 or GIF encoded by the
// ffmpeg executable (frames piped to it), or an OGV by VTK's Theora writer.
// A movie is written to a partial file and renamed when finished, so a
// cancelled or failed export leaves no broken file.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

namespace drape {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // One frame, RGB rows from the top, the size given at opening.
  virtual void Add(const std::vector<unsigned char>& rgb) = 0;
  // Completes the file (throws std::runtime_error if the encoder failed).
  virtual void Finish() = 0;
  // Stops and removes what was written (also what the destructor does
  // without Finish).
  virtual void Abort() = 0;
};

// By `output`: a name ending in .mp4, .gif or .ogv, else a folder (created)
// of frame_NNNN.png. Throws std::runtime_error when the encoder cannot start
// (no ffmpeg on PATH, an unwritable place).
std::unique_ptr<FrameSink> OpenFrameSink(const std::filesystem::path& output,
                                         int width,
                                         int height,
                                         double fps);

}  // namespace drape
