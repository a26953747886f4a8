#include "tests/ipu/support/libmpeg2_decode.hpp"

#include <cstring>
#include <stdexcept>

extern "C" {
#include <mpeg2.h>
}

namespace vbim::ipu::testing {

std::vector<Yuv420Image> decodeWithLibmpeg2(const std::vector<std::uint8_t>& es) {
  // No SIMD: the C IDCT and motion compensation (process-wide, before the first mpeg2_init()).
  mpeg2_accel(0);
  mpeg2dec_t* dec = mpeg2_init();
  if (!dec) throw std::runtime_error("mpeg2_init failed");
  const mpeg2_info_t* info = mpeg2_info(dec);
  std::vector<std::uint8_t> bytes = es;
  mpeg2_buffer(dec, bytes.data(), bytes.data() + bytes.size());
  std::vector<Yuv420Image> out;
  bool fed = false;
  for (;;) {
    const mpeg2_state_t state = mpeg2_parse(dec);
    if (state == STATE_BUFFER) {
      if (fed) break;
      static std::uint8_t end[4] = {0, 0, 1, 0xB7};  // flushes the last reference frame
      mpeg2_buffer(dec, end, end + 4);
      fed = true;
    } else if ((state == STATE_SLICE || state == STATE_END || state == STATE_INVALID_END) && info->display_fbuf) {
      const mpeg2_sequence_t& seq = *info->sequence;
      const int w = static_cast<int>(seq.picture_width);
      const int h = static_cast<int>(seq.picture_height);
      Yuv420Image img(w, h);
      for (int y = 0; y < h; ++y)
        std::memcpy(img.y.data() + static_cast<std::size_t>(y) * w, info->display_fbuf->buf[0] + y * seq.width,
                    static_cast<std::size_t>(w));
      for (int y = 0; y < img.chromaHeight(); ++y) {
        std::memcpy(img.cb.data() + static_cast<std::size_t>(y) * img.chromaWidth(),
                    info->display_fbuf->buf[1] + y * seq.chroma_width, static_cast<std::size_t>(img.chromaWidth()));
        std::memcpy(img.cr.data() + static_cast<std::size_t>(y) * img.chromaWidth(),
                    info->display_fbuf->buf[2] + y * seq.chroma_width, static_cast<std::size_t>(img.chromaWidth()));
      }
      out.push_back(std::move(img));
    }
  }
  mpeg2_close(dec);
  return out;
}

}  // namespace vbim::ipu::testing
