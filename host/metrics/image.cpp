#include "metrics/image.h"

#include "util/error.h"
#include "util/fileio.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <fmt/format.h>

#include <algorithm>
#include <exception>

namespace lb {

namespace {

// OpenEXR writes through an OStream; this one keeps the file in memory, so
// that the bytes reach the disk through util::writeFileAtomic (OpenEXR's own
// file stream does not report errors on close: a full disk left 0 bytes).
class MemoryOStream : public Imf::OStream {
public:
    MemoryOStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override
    {
        size_t end = pos_ + static_cast<size_t>(n);
        if (end > buf_.size()) buf_.resize(end);
        std::copy(c, c + n, buf_.begin() + static_cast<std::ptrdiff_t>(pos_));
        pos_ = end;
    }
    uint64_t tellp() override { return pos_; }
    void seekp(uint64_t pos) override { pos_ = static_cast<size_t>(pos); }
    std::string take() { return std::move(buf_); }

private:
    std::string buf_;
    size_t pos_ = 0;
};

}  // namespace

std::string encodeExr(const Image& img)
{
    std::vector<float> f(img.px.begin(), img.px.end());
    MemoryOStream os;
    try {
        Imf::Header header(img.width, img.height);
        header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(os, header);
        Imf::FrameBuffer fb;
        fb.insert("Y",
                  Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(f.data()), sizeof(float),
                             sizeof(float) * static_cast<size_t>(img.width)));
        file.setFrameBuffer(fb);
        file.writePixels(img.height);
    } catch (const std::exception& e) {
        throw Error(fmt::format("cannot encode a {} x {} OpenEXR image: {}", img.width, img.height, e.what()));
    }
    return os.take();
}

void writeExr(const std::string& path, const Image& img) { util::writeFileAtomic(path, encodeExr(img)); }

Image readExr(const std::string& path)
{
    try {
        Imf::InputFile file(path.c_str());
        auto dw = file.header().dataWindow();
        int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        if (!file.header().channels().findChannel("Y"))
            throw InputError(fmt::format("{}: expected an OpenEXR channel named Y (irradiance in lux)", path));
        std::vector<float> f(static_cast<size_t>(w) * h);
        Imf::FrameBuffer fb;
        char* base = reinterpret_cast<char*>(f.data()) -
            (static_cast<ptrdiff_t>(dw.min.x) + static_cast<ptrdiff_t>(dw.min.y) * w) * sizeof(float);
        fb.insert("Y", Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * static_cast<size_t>(w)));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        Image img(w, h);
        for (size_t i = 0; i < f.size(); ++i) img.px[i] = f[i];
        return img;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(fmt::format("{}: cannot read OpenEXR: {}", path, e.what()));
    }
}

}  // namespace lb
