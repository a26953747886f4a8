/* vbim_ref.h: a C99 reference of the computations a console port of vbim's pipeline must reproduce
 * bit for bit, written from vbim's model (docs/porting.md, "A C reference"): the frame hash of
 * hashes.txt, the GS blend (32-bit, and the 16-bit path with the GS dither), the IPU's colour
 * conversion (RGB32 and RGB16, SETTH thresholds, dither) and the IPU's IDCTs (pcsx2, libmpeg2, exact). No dependency
 * but <stdint.h>, <stddef.h> and <string.h>; every function is static, so a port includes the header where it needs it.
 * Each answer is checked against the vectors `vbim vectors` writes by tests/ref/vbim_ref_check.c.
 *
 * C leaves >> of a negative value and conversions of out-of-range values to signed types to the
 * implementation; this header never relies on either (vbim_ref_asr, vbim_ref_s32, vbim_ref_s16). */
#ifndef VBIM_REF_H
#define VBIM_REF_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* ---- helpers --------------------------------------------------------------------------------- */

/* floor(v / 2^s), whatever the compiler does with >> of a negative value. */
static inline int64_t vbim_ref_asr(int64_t v, int s) {
  if (v >= 0) return v >> s;
  return -(int64_t)((((uint64_t)(-(v + 1))) >> s) + 1);
}

/* The low 32 bits as a two's complement value (C's int arithmetic wrapping). */
static inline int64_t vbim_ref_s32(int64_t v) {
  const uint32_t u = (uint32_t)(uint64_t)v;
  return u <= 0x7fffffffu ? (int64_t)u : (int64_t)u - 4294967296LL;
}

/* The low 16 bits as a two's complement value (a store into a 16-bit sample). */
static inline int16_t vbim_ref_s16(int64_t v) {
  const uint16_t u = (uint16_t)(uint64_t)v;
  return (int16_t)(u <= 0x7fffu ? (int32_t)u : (int32_t)u - 65536);
}

static inline int vbim_ref_clamp(int v, int lo, int hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

/* ---- the frame hash (player/frame_hash.hpp, docs/player.md "hashes.txt") ----------------------- */

/* Four FNV-1a lanes fed 64-bit little-endian words by word index mod 4. */
typedef struct {
  uint64_t lanes[4];
  uint64_t count;
} vbim_ref_hash;

static inline void vbim_ref_hash_init(vbim_ref_hash* h) {
  int i;
  for (i = 0; i < 4; ++i) h->lanes[i] = 0xcbf29ce484222325ull + (uint64_t)i;
  h->count = 0;
}

static inline void vbim_ref_hash_word(vbim_ref_hash* h, uint64_t w) {
  uint64_t* l = &h->lanes[h->count & 3];
  *l = (*l ^ w) * 0x100000001b3ull;
  ++h->count;
}

/* One image: its header word (width << 32 | height), then its RGBA bytes as little-endian words,
 * the last zero-padded. A vsync's line hashes the lightmap, then the sky. */
static inline void vbim_ref_hash_image(vbim_ref_hash* h, uint32_t width, uint32_t height, const uint8_t* rgba) {
  const size_t n = (size_t)width * height * 4;
  size_t i;
  vbim_ref_hash_word(h, ((uint64_t)width << 32) | height);
  for (i = 0; i < n; i += 8) {
    uint64_t w = 0;
    int k;
    for (k = 7; k >= 0; --k) w = (w << 8) | (i + (size_t)k < n ? rgba[i + (size_t)k] : 0);
    vbim_ref_hash_word(h, w);
  }
}

static inline uint64_t vbim_ref_rotl(uint64_t x, int r) {
  return (x << r) | (x >> (64 - r));
}

/* The lanes folded, then the splitmix64 finaliser. */
static inline uint64_t vbim_ref_hash_digest(const vbim_ref_hash* h) {
  uint64_t v =
      h->lanes[0] ^ vbim_ref_rotl(h->lanes[1], 16) ^ vbim_ref_rotl(h->lanes[2], 32) ^ vbim_ref_rotl(h->lanes[3], 48);
  v ^= v >> 30;
  v *= 0xbf58476d1ce4e5b9ull;
  v ^= v >> 27;
  v *= 0x94d049bb133111ebull;
  v ^= v >> 31;
  return v;
}

/* ---- the GS blend (gs/blend.hpp, gs/blend16.hpp) ---------------------------------------------- */

/* ALPHA_1 = (Cs, Cd, FIX, Cd): Cv = (((Cs - Cd) * FIX) >> 7) + Cd with an arithmetic shift (floor),
 * then COLCLAMP: clamp to 0..255 (colclamp 1) or keep the low 8 bits (0). */
static inline int vbim_ref_blend_channel(int cs, int cd, int fix, int colclamp) {
  const int v = (int)vbim_ref_asr((int64_t)(cs - cd) * fix, 7) + cd;
  return colclamp ? vbim_ref_clamp(v, 0, 255) : (v & 0xFF);
}

/* A span of RGBA8 pixels blended in place, as the lightmap draw does (TFX MODULATE with vertex
 * colour 0x80 passes the texel through): dst = blend(src, dst) per colour channel, alpha As, or
 * the old Ad when keep_alpha (FRAME.FBMSK = 0xFF000000). */
static inline void vbim_ref_blend_span(uint8_t* dst, const uint8_t* src, size_t pixels, int fix, int colclamp,
                                       int keep_alpha) {
  size_t i;
  int c;
  for (i = 0; i < pixels; ++i) {
    for (c = 0; c < 3; ++c)
      dst[4 * i + c] = (uint8_t)vbim_ref_blend_channel(src[4 * i + c], dst[4 * i + c], fix, colclamp);
    if (!keep_alpha) dst[4 * i + 3] = src[4 * i + 3];
  }
}

/* DIMX as GS_SET_DIMX(4,2,5,3, 0,6,1,7, 5,3,4,2, 1,7,0,6) sets it, [y & 3][x & 3]. */
static const int vbim_ref_dimx[4][4] = {{-4, 2, -3, 3}, {0, -2, 1, -1}, {-3, 3, -4, 2}, {1, -1, 0, -2}};

/* The 16-bit path, one channel of texels as the GS expands them (5-bit value << 3): the blend plus
 * DIMX (dither 0 without DTHE), & 0xFF when COLCLAMP is 0, clamped, then the top 5 bits kept. */
static inline int vbim_ref_blend16_channel(int cs, int cd, int fix, int dither, int colclamp) {
  int v = (int)vbim_ref_asr((int64_t)(cs - cd) * fix, 7) + cd + dither;
  if (!colclamp) v &= 0xFF;
  return vbim_ref_clamp(v, 0, 255) & 0xF8;
}

/* `rows` rows of `pixels` expanded texels (strides in bytes), the first at (x0, y0) of the texture
 * (for DIMX): the 16-bit draw with DTHE = dthe. The written alpha is bit 7 of As (the texel's bit
 * 15), or the old one when keep_alpha. */
static inline void vbim_ref_blend16_rect(uint8_t* dst, size_t dst_stride, const uint8_t* src, size_t src_stride,
                                         size_t pixels, size_t rows, int x0, int y0, int fix, int colclamp, int dthe,
                                         int keep_alpha) {
  size_t r, i;
  int c;
  for (r = 0; r < rows; ++r) {
    uint8_t* d = dst + r * dst_stride;
    const uint8_t* s = src + r * src_stride;
    for (i = 0; i < pixels; ++i) {
      const int dither = dthe ? vbim_ref_dimx[(y0 + (int)r) & 3][(x0 + (int)i) & 3] : 0;
      for (c = 0; c < 3; ++c)
        d[4 * i + c] = (uint8_t)vbim_ref_blend16_channel(s[4 * i + c], d[4 * i + c], fix, dither, colclamp);
      if (!keep_alpha) d[4 * i + 3] = (uint8_t)(s[4 * i + 3] & 0x80);
    }
  }
}

/* ---- the IPU's colour conversion (ipu/csc.hpp) ------------------------------------------------ */

/* BT.601 with coefficients x 128, each term >> 6 (floor), then (sum + 1) >> 1, clamped. */
static inline void vbim_ref_ycbcr_to_rgb(int y, int cb, int cr, uint8_t rgb[3]) {
  const int lum = (0x95 * (y > 16 ? y - 16 : 0)) >> 6;
  const int rcr = (int)vbim_ref_asr(0xCC * (cr - 128), 6);
  const int gcr = (int)vbim_ref_asr(-0x68 * (cr - 128), 6);
  const int gcb = (int)vbim_ref_asr(-0x32 * (cb - 128), 6);
  const int bcb = (int)vbim_ref_asr(0x102 * (cb - 128), 6);
  rgb[0] = (uint8_t)vbim_ref_clamp((int)vbim_ref_asr(lum + rcr + 1, 1), 0, 255);
  rgb[1] = (uint8_t)vbim_ref_clamp((int)vbim_ref_asr(lum + gcr + gcb + 1, 1), 0, 255);
  rgb[2] = (uint8_t)vbim_ref_clamp((int)vbim_ref_asr(lum + bcb + 1, 1), 0, 255);
}

/* One RGB32 pixel with SETTH: R, G, B all below TH0 -> 0, 0, 0, 0; else all below TH1 -> alpha
 * 0x40; else 0x80 (th0 = th1 = 0: always 0x80). */
static inline void vbim_ref_csc_pixel(int y, int cb, int cr, int th0, int th1, uint8_t out[4]) {
  int m;
  vbim_ref_ycbcr_to_rgb(y, cb, cr, out);
  m = out[0] > out[1] ? out[0] : out[1];
  m = m > out[2] ? m : out[2];
  if (m < th0) {
    out[0] = out[1] = out[2] = out[3] = 0;
  } else {
    out[3] = (uint8_t)(m < th1 ? 0x40 : 0x80);
  }
}

/* The IPU's RGB16 dither (DTE = 1), [y & 3][x & 3] of the picture. */
static const int vbim_ref_ipu_dither[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};

/* RGB16 of an RGB32 pixel at (x, y): 5 bits a channel (dithered first when dte), bit 15 set where
 * the alpha was 0x40. */
static inline uint16_t vbim_ref_rgb16(const uint8_t rgba[4], int x, int y, int dte) {
  int v[3], k;
  for (k = 0; k < 3; ++k) {
    int s = rgba[k];
    if (dte) s = vbim_ref_clamp(s + vbim_ref_ipu_dither[y & 3][x & 3], 0, 255);
    v[k] = s >> 3;
  }
  return (uint16_t)(v[0] | (v[1] << 5) | (v[2] << 10) | ((rgba[3] == 0x40 ? 1 : 0) << 15));
}

/* A macroblock as csc.txt lists it (Y 16x16, Cb 8x8, Cr 8x8: 384 bytes) to 16 rows of 16 RGB32
 * pixels (1024 bytes), or, with ofm 1, RGB16 little-endian pixels (512 bytes). A macroblock starts
 * on a multiple of 16, so its own coordinates index the dither. */
static inline void vbim_ref_csc_macroblock(const uint8_t ycbcr[384], int ofm, int dte, int th0, int th1, uint8_t* out) {
  int x, y;
  for (y = 0; y < 16; ++y) {
    for (x = 0; x < 16; ++x) {
      uint8_t px[4];
      const int c = 8 * (y >> 1) + (x >> 1);
      vbim_ref_csc_pixel(ycbcr[16 * y + x], ycbcr[256 + c], ycbcr[320 + c], th0, th1, px);
      if (ofm == 0) {
        memcpy(out + 4 * (16 * y + x), px, 4);
      } else {
        const uint16_t p = vbim_ref_rgb16(px, x, y, dte);
        out[2 * (16 * y + x)] = (uint8_t)(p & 0xFF);
        out[2 * (16 * y + x) + 1] = (uint8_t)(p >> 8);
      }
    }
  }
}

/* ---- the IPU's IDCT (ipu/idct_libmpeg2.hpp: ipu.idct = "pcsx2", the default) ------------------- */

/* One 1-D pass of the libmpeg2-family transform over x[0], x[step], ... x[7 step]: W_k =
 * round(2048 sqrt(2) cos(k pi / 16)), sums in 32-bit int that wrap as C int does on the reference
 * decoders, results (a + b) >> shift stored as 16-bit samples. The odd part's sqrt(1/2) is 181 /
 * 256: form 0 (PCSX2's rows) ((u + v) * 181) >> 8; form 1 (PCSX2's columns) ((u >> 8) + (v >> 8))
 * * 181; form 2 (libmpeg2 0.5.1) ((u + v) >> 8) * 181. */
static inline void vbim_ref_idct_pass(int16_t* x, int step, int64_t bias, int shift, int form) {
  const int64_t x0 = x[0], x1 = x[step], x2 = x[2 * step], x3 = x[3 * step], x4 = x[4 * step], x5 = x[5 * step],
                x6 = x[6 * step], x7 = x[7 * step];
  const int64_t d0 = vbim_ref_s32(x0 * 2048 + bias), d4 = vbim_ref_s32(x4 * 2048);
  const int64_t e0 = vbim_ref_s32(d0 + d4), e1 = vbim_ref_s32(d0 - d4);
  const int64_t e2 = vbim_ref_s32(1108 * x6 + 2676 * x2), e3 = vbim_ref_s32(1108 * x2 - 2676 * x6);
  const int64_t a0 = vbim_ref_s32(e0 + e2), a1 = vbim_ref_s32(e1 + e3), a2 = vbim_ref_s32(e1 - e3),
                a3 = vbim_ref_s32(e0 - e2);
  const int64_t o0 = vbim_ref_s32(565 * x7 + 2841 * x1), o1 = vbim_ref_s32(565 * x1 - 2841 * x7);
  const int64_t o2 = vbim_ref_s32(2408 * x3 + 1609 * x5), o3 = vbim_ref_s32(2408 * x5 - 1609 * x3);
  const int64_t b0 = vbim_ref_s32(o0 + o2), b3 = vbim_ref_s32(o1 + o3);
  int64_t u = vbim_ref_s32(o0 - o2), v = vbim_ref_s32(o1 - o3), b1, b2;
  if (form == 1) {
    u = vbim_ref_asr(u, 8);
    v = vbim_ref_asr(v, 8);
    b1 = vbim_ref_s32((u + v) * 181);
    b2 = vbim_ref_s32((u - v) * 181);
  } else if (form == 2) {
    b1 = vbim_ref_s32(vbim_ref_asr(vbim_ref_s32(u + v), 8) * 181);
    b2 = vbim_ref_s32(vbim_ref_asr(vbim_ref_s32(u - v), 8) * 181);
  } else {
    b1 = vbim_ref_asr(vbim_ref_s32(vbim_ref_s32(u + v) * 181), 8);
    b2 = vbim_ref_asr(vbim_ref_s32(vbim_ref_s32(u - v) * 181), 8);
  }
  x[0] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a0 + b0), shift));
  x[step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a1 + b1), shift));
  x[2 * step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a2 + b2), shift));
  x[3 * step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a3 + b3), shift));
  x[4 * step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a3 - b3), shift));
  x[5 * step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a2 - b2), shift));
  x[6 * step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a1 - b1), shift));
  x[7 * step] = vbim_ref_s16(vbim_ref_asr(vbim_ref_s32(a0 - b0), shift));
}

/* Rows, then columns, on 16-bit samples; `scale` multiplies each coefficient on entry. A row
 * holding only its first coefficient becomes 8 x that coefficient / scale. */
static inline void vbim_ref_idct_family(const int16_t in[64], int16_t out[64], int scale, int64_t row_bias,
                                        int row_shift, int row_form, int col_form) {
  int16_t b[64];
  int r, c;
  for (r = 0; r < 64; ++r) b[r] = vbim_ref_s16((int64_t)in[r] * scale);
  for (r = 0; r < 8; ++r) {
    int16_t* row = b + 8 * r;
    if ((row[1] | row[2] | row[3] | row[4] | row[5] | row[6] | row[7]) == 0) {
      const int16_t v = vbim_ref_s16((int64_t)row[0] * 8 / scale);
      for (c = 0; c < 8; ++c) row[c] = v;
    } else {
      vbim_ref_idct_pass(row, 1, row_bias, row_shift, row_form);
    }
  }
  for (c = 0; c < 8; ++c) vbim_ref_idct_pass(b + c, 8, 65536, 17, col_form);
  memcpy(out, b, sizeof b);
}

/* PCSX2's IPU IDCT: 64 dequantised coefficients (raster order, -2048..2047) to the 64 results
 * before any clip (idct.txt `result`). Rows: + 128, >> 8; columns: + 65536, >> 17. */
static inline void vbim_ref_idct_pcsx2(const int16_t in[64], int16_t out[64]) {
  vbim_ref_idct_family(in, out, 1, 128, 8, 0, 1);
}

/* libmpeg2 0.5.1's C IDCT (ipu.idct = "libmpeg2"): coefficients x 16; rows + 2048, >> 12. */
static inline void vbim_ref_idct_libmpeg2(const int16_t in[64], int16_t out[64]) {
  vbim_ref_idct_family(in, out, 16, 2048, 12, 2, 2);
}

/* What IDEC writes for an intra block: the results clamped to 0..255 (idct.txt `pixels`). */
static inline void vbim_ref_idct_pixels(const int16_t result[64], uint8_t pixels[64]) {
  int i;
  for (i = 0; i < 64; ++i) pixels[i] = (uint8_t)vbim_ref_clamp(result[i], 0, 255);
}

/* ---- the exact IDCT (ipu/idct.hpp: ipu.idct = "exact") ----------------------------------------- */

/* floor((sum_u sum_v F(v,u) W(u,x) W(v,y) + 2^30) / 2^31) with W_k = round(2^14 sqrt(2) cos(k pi
 * / 16)) (W_4 = 2^14), rows exact in 32 bits, columns in 64 bits: one exact integer expression. */
static inline void vbim_ref_idct_exact(const int16_t in[64], int16_t out[64]) {
  static const int64_t w[8] = {16384, 22725, 21407, 19266, 16384, 12873, 8867, 4520};
  int64_t r[64];
  int v, u, n, k;
  /* cos((2n + 1) k pi / 16) as +-W_m: the index (2n + 1) k mod 32 folded into 0..8 with a sign. */
  for (v = 0; v < 8; ++v) {
    for (n = 0; n < 8; ++n) {
      int64_t s = 0;
      for (u = 0; u < 8; ++u) {
        int m = ((2 * n + 1) * u) % 32, sign = 1;
        if (m > 16) m = 32 - m;
        if (m > 8) {
          m = 16 - m;
          sign = -1;
        }
        s += (m == 8 ? 0 : sign * (u == 0 ? 16384 : w[m])) * (int64_t)in[8 * v + u];
      }
      r[8 * v + n] = s;
    }
  }
  for (n = 0; n < 8; ++n) {
    for (k = 0; k < 8; ++k) {
      int64_t s = (int64_t)1 << 30;
      for (v = 0; v < 8; ++v) {
        int m = ((2 * k + 1) * v) % 32, sign = 1;
        if (m > 16) m = 32 - m;
        if (m > 8) {
          m = 16 - m;
          sign = -1;
        }
        s += (m == 8 ? 0 : sign * (v == 0 ? 16384 : w[m])) * r[8 * v + n];
      }
      out[8 * k + n] = (int16_t)vbim_ref_asr(s, 31);
    }
  }
}

#endif /* VBIM_REF_H */
