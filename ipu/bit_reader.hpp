// Big-endian bit reader over one bounded byte range (one slice or one header). Reads past the end
// return zero bits and are counted, so a truncated slice can never read another slice's bytes or
// out of bounds: the caller checks overrun() and ends the slice (ISO/IEC 13818-2 §5.2 nextbits()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace vbim::ipu {

class BitReader {
 public:
  BitReader() = default;
  BitReader(const std::uint8_t* begin, const std::uint8_t* end) : begin_(begin), p_(begin), end_(end) { refill(); }

  // The next n bits (1..32) without consuming them.
  std::uint32_t peek(int n) const { return static_cast<std::uint32_t>(cache_ >> (64 - n)); }
  void skip(int n) {
    cache_ <<= n;
    count_ -= n;
    if (count_ < 32) refill();
  }
  // For the serial loop of AC codes: topUp() leaves at least 56 valid bits (the cache is refilled
  // whole, no data-dependent branch), then skipUnchecked() consumes codes without looking at the
  // count, as long as the caller keeps to that budget. peek(n) needs n <= the bits left.
  void topUp() {
    if (end_ - p_ >= 8) [[likely]] {
      std::uint64_t v;
      std::memcpy(&v, p_, 8);
      v = __builtin_bswap64(v);
      cache_ |= v >> count_;  // bits already in the cache are the same bits (OR is idempotent)
      const int bytes = (63 - count_) >> 3;
      p_ += bytes;
      count_ += bytes * 8;
    } else {
      refill();
    }
  }
  void skipUnchecked(int n) {
    cache_ <<= n;
    count_ -= n;
  }
  std::uint32_t read(int n) {
    const std::uint32_t v = peek(n);
    skip(n);
    return v;
  }
  bool readBit() { return read(1) != 0; }
  // Signed n-bit two's complement value.
  std::int32_t readSigned(int n) {
    const std::uint32_t v = read(n);
    return static_cast<std::int32_t>(v << (32 - n)) >> (32 - n);
  }

  // Valid bits in the cache (peek(n) needs n of them).
  int bitsCached() const { return count_; }
  // Bits consumed since the start of the range.
  std::size_t position() const { return (static_cast<std::size_t>(p_ - begin_) + pad_) * 8 - count_; }
  std::size_t sizeBits() const { return static_cast<std::size_t>(end_ - begin_) * 8; }
  // True once more bits were consumed than the range holds.
  bool overrun() const { return position() > sizeBits(); }
  std::size_t bitsLeft() const { return overrun() ? 0 : sizeBits() - position(); }
  // Byte offset (from the start of the range) of the next unread bit.
  std::size_t bytePosition() const { return position() / 8; }

 private:
  // Keeps at least 32 (normally 57..64; at least 56 when called with fewer than 56) valid bits in
  // the cache, zero bits past the end.
  void refill() {
    if (end_ - p_ >= 8) [[likely]] {
      std::uint64_t v;
      std::memcpy(&v, p_, 8);
      v = __builtin_bswap64(v);
      cache_ |= v >> count_;
      const int bytes = (63 - count_) >> 3;
      p_ += bytes;
      count_ += bytes * 8;
      return;
    }
    const Tail t = refillTail(cache_, count_, p_, end_);
    cache_ = t.cache;
    count_ = t.count;
    p_ = t.p;
    pad_ += t.pad;
  }

  // The last few bytes, one at a time. State in and out by value, so a decoder that copies its
  // reader into a local keeps it in registers (the address of the copy never escapes).
  struct Tail {
    std::uint64_t cache;
    int count;
    const std::uint8_t* p;
    std::size_t pad;
  };
  [[gnu::noinline]] static Tail refillTail(std::uint64_t cache, int count, const std::uint8_t* p,
                                           const std::uint8_t* end) {
    std::size_t pad = 0;
    while (count <= 56) {
      std::uint64_t b = 0;
      if (p < end) {
        b = *p++;
      } else {
        ++pad;
      }
      cache |= b << (56 - count);
      count += 8;
    }
    return Tail{cache, count, p, pad};
  }

  const std::uint8_t* begin_ = nullptr;
  const std::uint8_t* p_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  std::uint64_t cache_ = 0;  // left-aligned: the next bit is bit 63
  int count_ = 0;            // valid bits in cache_
  std::size_t pad_ = 0;      // zero bytes supplied past the end
};

}  // namespace vbim::ipu
