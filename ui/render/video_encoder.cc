#include "ui/render/video_encoder.h"

#include <vtkImageData.h>
#include <vtkOggTheoraWriter.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace drape {
namespace fs = std::filesystem;
namespace {

template <typename T>
using Ptr = vtkSmartPointer<T>;

// RGB rows from the top as VTK's image (rows from the bottom).
Ptr<vtkImageData> ImageOf(const std::vector<unsigned char>& rgb, int width, int height) {
  auto image = Ptr<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  const size_t row = static_cast<size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    std::memcpy(data + row * (height - 1 - y), rgb.data() + row * y, row);
  return image;
}

fs::path Partial(const fs::path& output) {
  fs::path p = output;
  p.replace_filename(output.stem().string() + ".partial" + output.extension().string());
  return p;
}

class PngFolder final : public FrameSink {
 public:
  PngFolder(fs::path dir, int w, int h) : dir_(std::move(dir)), width_(w), height_(h) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) throw std::runtime_error("cannot create " + dir_.string() + ": " + ec.message());
  }
  void Add(const std::vector<unsigned char>& rgb) override {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%04d.png", ++count_);
    const fs::path file = dir_ / name;
    auto writer = Ptr<vtkPNGWriter>::New();
    writer->SetFileName(file.string().c_str());
    writer->SetInputData(ImageOf(rgb, width_, height_));
    writer->Write();
    if (writer->GetErrorCode() != 0) throw std::runtime_error("cannot write " + file.string());
  }
  void Finish() override {}
  void Abort() override {}  // the frames written so far are kept: each is whole

 private:
  fs::path dir_;
  int width_, height_;
  int count_ = 0;
};

class Ffmpeg final : public FrameSink {
 public:
  Ffmpeg(fs::path output, int w, int h, double fps)
      : output_(std::move(output)), partial_(Partial(output_)), frame_bytes_(size_t(w) * h * 3) {
    if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0)
      throw std::runtime_error(
          "ffmpeg was not found on PATH: it encodes MP4 and GIF (Debian: apt install ffmpeg); "
          "or export to .ogv or a folder of PNGs");
    const std::string ext = output_.extension().string();
    std::string filters, codec;
    if (ext == ".gif") {
      filters = "-vf \"split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse\"";
    } else {  // H.264 needs even sizes
      filters = "-vf \"pad=ceil(iw/2)*2:ceil(ih/2)*2\"";
      codec = "-c:v libx264 -pix_fmt yuv420p -movflags +faststart";
    }
    const std::string command =
        "ffmpeg -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " +
        std::to_string(w) + "x" + std::to_string(h) + " -r " + std::to_string(fps) + " -i - " +
        filters + " " + codec + " '" + partial_.string() + "'";
    // A dying ffmpeg must not kill us with SIGPIPE: writes then fail instead.
    std::signal(SIGPIPE, SIG_IGN);
    pipe_ = popen(command.c_str(), "w");
    if (!pipe_) throw std::runtime_error("cannot start ffmpeg");
  }
  ~Ffmpeg() override {
    if (pipe_) Abort();
  }
  void Add(const std::vector<unsigned char>& rgb) override {
    if (rgb.size() != frame_bytes_) throw std::invalid_argument("frame of the wrong size");
    if (std::fwrite(rgb.data(), 1, rgb.size(), pipe_) != rgb.size())
      throw std::runtime_error("ffmpeg stopped taking frames while writing " + output_.string());
  }
  void Finish() override {
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    std::error_code ec;
    if (status != 0) {
      fs::remove(partial_, ec);
      throw std::runtime_error("ffmpeg failed to encode " + output_.string());
    }
    fs::rename(partial_, output_, ec);
    if (ec) throw std::runtime_error("cannot write " + output_.string() + ": " + ec.message());
  }
  void Abort() override {
    if (pipe_) pclose(pipe_);
    pipe_ = nullptr;
    std::error_code ec;
    fs::remove(partial_, ec);
  }

 private:
  fs::path output_, partial_;
  size_t frame_bytes_;
  FILE* pipe_ = nullptr;
};

class Theora final : public FrameSink {
 public:
  Theora(fs::path output, int w, int h, double fps)
      : output_(std::move(output)), partial_(Partial(output_)), width_(w), height_(h) {
    writer_->SetFileName(partial_.string().c_str());
    writer_->SetRate(static_cast<int>(std::lround(fps)));
    writer_->SetQuality(2);
    writer_->SetInputData(ImageOf(std::vector<unsigned char>(size_t(w) * h * 3, 0), w, h));
  }
  ~Theora() override {
    if (started_) Abort();
  }
  void Add(const std::vector<unsigned char>& rgb) override {
    writer_->SetInputData(ImageOf(rgb, width_, height_));
    if (!started_) {
      writer_->Start();
      started_ = true;
    }
    writer_->Write();
    if (writer_->GetError()) throw std::runtime_error("cannot write " + output_.string());
  }
  void Finish() override {
    if (started_) writer_->End();
    started_ = false;
    std::error_code ec;
    fs::rename(partial_, output_, ec);
    if (ec) throw std::runtime_error("cannot write " + output_.string() + ": " + ec.message());
  }
  void Abort() override {
    if (started_) writer_->End();
    started_ = false;
    std::error_code ec;
    fs::remove(partial_, ec);
  }

 private:
  fs::path output_, partial_;
  int width_, height_;
  bool started_ = false;
  Ptr<vtkOggTheoraWriter> writer_ = Ptr<vtkOggTheoraWriter>::New();
};

}  // namespace

std::unique_ptr<FrameSink> OpenFrameSink(const fs::path& output,
                                         int width,
                                         int height,
                                         double fps) {
  const std::string ext = output.extension().string();
  if (ext == ".mp4" || ext == ".gif") return std::make_unique<Ffmpeg>(output, width, height, fps);
  if (ext == ".ogv") return std::make_unique<Theora>(output, width, height, fps);
  return std::make_unique<PngFolder>(output, width, height);
}

}  // namespace drape
