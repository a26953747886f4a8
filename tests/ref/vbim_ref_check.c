/* Checks ref/vbim_ref.h against the vectors `vbim vectors` writes: every entry the header can
 * compute (frame_hash.txt, blend.txt, idct.txt for the IDCT its header names, csc.txt, draw.txt)
 * is computed with the header and compared. Compiled as C99 with -pedantic (tests/ref/CMakeLists.txt).
 * Usage: vbim_ref_check DIR. Exit 0 when every entry matches, 1 when one differs, 2 on a missing
 * or malformed file. */
#include <stdio.h>
#include <stdlib.h>

#include "vbim_ref.h"

typedef struct {
  char* key;
  char* value;
} entry;

typedef struct {
  const char* name;
  entry* e;
  size_t n;
  char idct[32]; /* the "# IDCT: NAME" header line's NAME, if any */
  size_t checked;
  size_t failed;
} vfile;

static char* dup_range(const char* s, size_t n) {
  char* d = (char*)malloc(n + 1);
  if (!d) exit(2);
  memcpy(d, s, n);
  d[n] = 0;
  return d;
}

static void load(const char* dir, const char* name, vfile* f) {
  char path[4096], line[1 << 16];
  FILE* in;
  size_t cap = 0;
  memset(f, 0, sizeof *f);
  f->name = name;
  sprintf(path, "%.4000s/%s", dir, name);
  in = fopen(path, "r");
  if (!in) {
    fprintf(stderr, "%s: cannot open\n", path);
    exit(2);
  }
  while (fgets(line, sizeof line, in)) {
    size_t len = strlen(line);
    char* space;
    while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = 0;
    if (len == 0) continue;
    if (line[0] == '#') {
      if (strncmp(line, "# IDCT: ", 8) == 0) sscanf(line + 8, "%31s", f->idct);
      continue;
    }
    space = strchr(line, ' ');
    if (!space) {
      fprintf(stderr, "%s: not KEY VALUE: %s\n", path, line);
      exit(2);
    }
    if (f->n == cap) {
      cap = cap ? 2 * cap : 256;
      f->e = (entry*)realloc(f->e, cap * sizeof(entry));
      if (!f->e) exit(2);
    }
    f->e[f->n].key = dup_range(line, (size_t)(space - line));
    f->e[f->n].value = dup_range(space + 1, strlen(space + 1));
    ++f->n;
  }
  fclose(in);
}

static void release(vfile* f) {
  size_t i;
  for (i = 0; i < f->n; ++i) {
    free(f->e[i].key);
    free(f->e[i].value);
  }
  free(f->e);
  f->e = NULL;
  f->n = 0;
}

static const char* find(const vfile* f, const char* key) {
  size_t i;
  for (i = 0; i < f->n; ++i)
    if (strcmp(f->e[i].key, key) == 0) return f->e[i].value;
  return NULL;
}

static int ends_with(const char* s, const char* tail) {
  const size_t n = strlen(s), t = strlen(tail);
  return n >= t && strcmp(s + n - t, tail) == 0;
}

/* Records one comparison; prints the first few failures of a file. */
static void expect(vfile* f, const char* key, const char* expected, const char* computed) {
  ++f->checked;
  if (expected && strcmp(expected, computed) == 0) return;
  if (++f->failed <= 3) {
    fprintf(stderr, "%s: %s: the vectors say '%.80s', vbim_ref.h computes '%.80s'\n", f->name, key,
            expected ? expected : "(missing)", computed);
  }
}

static void to_hex(const uint8_t* p, size_t n, char* out) {
  static const char digits[] = "0123456789abcdef";
  size_t i;
  for (i = 0; i < n; ++i) {
    out[2 * i] = digits[p[i] >> 4];
    out[2 * i + 1] = digits[p[i] & 15];
  }
  out[2 * n] = 0;
}

static size_t from_hex(const char* s, uint8_t* out, size_t max) {
  size_t n = 0;
  unsigned v;
  while (n < max && s[2 * n] && sscanf(s + 2 * n, "%2x", &v) == 1) out[n++] = (uint8_t)v;
  return n;
}

static void to_ints(const int16_t* v, int n, char* out) {
  int i;
  out[0] = 0;
  for (i = 0; i < n; ++i) sprintf(out + strlen(out), i ? ",%d" : "%d", v[i]);
}

/* frame_hash.txt: pattern images hashed. */
static void check_frame_hash(vfile* f) {
  size_t i;
  for (i = 0; i < f->n; ++i) {
    unsigned w[2] = {0, 0}, h[2] = {0, 0}, seed[2] = {0, 0};
    int images = sscanf(f->e[i].key, "frame_hash/lightmap=%ux%u:%u,sky=%ux%u:%u", &w[0], &h[0], &seed[0], &w[1], &h[1],
                        &seed[1]);
    vbim_ref_hash hash;
    char got[17];
    int k;
    if (images != 3 && images != 6) continue;
    vbim_ref_hash_init(&hash);
    for (k = 0; k < images / 3; ++k) {
      const size_t n = (size_t)w[k] * h[k] * 4;
      uint8_t* img = (uint8_t*)malloc(n ? n : 1);
      size_t b;
      if (!img) exit(2);
      for (b = 0; b < n; ++b) img[b] = (uint8_t)((b * 131 + seed[k] * 7 + (b >> 8)) & 0xFF);
      vbim_ref_hash_image(&hash, w[k], h[k], img);
      free(img);
    }
    sprintf(got, "%016llx", (unsigned long long)vbim_ref_hash_digest(&hash));
    expect(f, f->e[i].key, f->e[i].value, got);
  }
}

/* blend.txt: one channel, and the steps toward a target. */
static void check_blend(vfile* f) {
  size_t i;
  for (i = 0; i < f->n; ++i) {
    int cs, cd, fix, k;
    char mode[8], got[256];
    if (sscanf(f->e[i].key, "blend/cs=%d,cd=%d,fix=%d,colclamp=%7s", &cs, &cd, &fix, mode) == 4) {
      sprintf(got, "%d", vbim_ref_blend_channel(cs, cd, fix, strcmp(mode, "clamp") == 0));
      expect(f, f->e[i].key, f->e[i].value, got);
    } else if (sscanf(f->e[i].key, "blend_steps/cs=%d,cd=%d,fix=%d,colclamp=%7s", &cs, &cd, &fix, mode) == 4) {
      got[0] = 0;
      for (k = 0; k < 24; ++k) {
        const int next = vbim_ref_blend_channel(cs, cd, fix, 1);
        sprintf(got + strlen(got), k ? " %d" : "%d", next);
        if (next == cd) break;
        cd = next;
      }
      expect(f, f->e[i].key, f->e[i].value, got);
    }
  }
}

/* idct.txt: every `in` through the IDCT the header names (with the P and B pictures of a GOP
   stream, non-intra blocks too). */
static void check_idct(vfile* f) {
  size_t i;
  void (*idct)(const int16_t*, int16_t*) = NULL;
  if (strcmp(f->idct, "pcsx2") == 0) idct = vbim_ref_idct_pcsx2;
  if (strcmp(f->idct, "libmpeg2") == 0) idct = vbim_ref_idct_libmpeg2;
  if (strcmp(f->idct, "exact") == 0) idct = vbim_ref_idct_exact;
  if (!idct) {
    fprintf(stderr, "%s: no IDCT named in the header ('%s')\n", f->name, f->idct);
    exit(2);
  }
  for (i = 0; i < f->n; ++i) {
    int16_t in[64], out[64], px16[64];
    uint8_t px[64];
    char key[512], got[1024];
    const char* p = f->e[i].value;
    int k;
    if (!ends_with(f->e[i].key, "/in")) continue;
    for (k = 0; k < 64; ++k) {
      char* end;
      in[k] = (int16_t)strtol(p, &end, 10);
      p = *end == ',' ? end + 1 : end;
    }
    idct(in, out);
    vbim_ref_idct_pixels(out, px);
    for (k = 0; k < 64; ++k) px16[k] = px[k];
    sprintf(key, "%.*s/result", (int)(strlen(f->e[i].key) - 3), f->e[i].key);
    to_ints(out, 64, got);
    expect(f, key, find(f, key), got);
    /* Intra blocks only: a non-intra block's result is a residual the EE adds to its prediction. */
    sprintf(key, "%.*s/pixels", (int)(strlen(f->e[i].key) - 3), f->e[i].key);
    to_ints(px16, 64, got);
    if (find(f, key)) expect(f, key, find(f, key), got);
  }
}

/* csc.txt: every macroblock's six outputs. */
static void check_csc(vfile* f) {
  static const struct {
    const char* name;
    int ofm, dte, th;
  } outputs[] = {{"rgb32", 0, 0, 0},    {"rgb16", 1, 0, 0},    {"rgb16_dither", 1, 1, 0},
                 {"rgb32_th", 0, 0, 1}, {"rgb16_th", 1, 0, 1}, {"rgb16_dither_th", 1, 1, 1}};
  size_t i;
  for (i = 0; i < f->n; ++i) {
    uint8_t ycbcr[384], out[1024];
    char key[512], got[2049];
    size_t o;
    if (!ends_with(f->e[i].key, "/ycbcr")) continue;
    if (from_hex(f->e[i].value, ycbcr, sizeof ycbcr) != sizeof ycbcr) {
      fprintf(stderr, "%s: %s: not 384 bytes of hex\n", f->name, f->e[i].key);
      exit(2);
    }
    for (o = 0; o < sizeof outputs / sizeof outputs[0]; ++o) {
      vbim_ref_csc_macroblock(ycbcr, outputs[o].ofm, outputs[o].dte, outputs[o].th ? 32 : 0, outputs[o].th ? 96 : 0,
                              out);
      sprintf(key, "%.*s/%s", (int)(strlen(f->e[i].key) - 6), f->e[i].key, outputs[o].name);
      to_hex(out, outputs[o].ofm ? 512 : 1024, got);
      expect(f, key, find(f, key), got);
    }
  }
}

/* draw.txt: each draw from its setup, source and destination (an 8x4 texture at (0, 0)). */
static void check_draw(vfile* f) {
  size_t i;
  for (i = 0; i < f->n; ++i) {
    unsigned fix;
    int psm, dthe;
    char mode[8], base[512], key[600], got[257];
    const char *src_hex, *dst_hex;
    uint8_t src[128], dst[128];
    if (!ends_with(f->e[i].key, "/setup")) continue;
    if (sscanf(f->e[i].value, "fix=0x%x,colclamp=%7[a-z],psm=ct%d,dthe=%d", &fix, mode, &psm, &dthe) != 4) {
      fprintf(stderr, "%s: %s: setup '%s' not understood\n", f->name, f->e[i].key, f->e[i].value);
      exit(2);
    }
    sprintf(base, "%.*s", (int)(strlen(f->e[i].key) - 6), f->e[i].key);
    sprintf(key, "%s/source", base);
    src_hex = find(f, key);
    sprintf(key, "%s/destination", base);
    dst_hex = find(f, key);
    if (!src_hex || !dst_hex || from_hex(src_hex, src, 128) != 128 || from_hex(dst_hex, dst, 128) != 128) {
      fprintf(stderr, "%s: %s: no 8x4 source or destination\n", f->name, base);
      exit(2);
    }
    if (psm == 16) {
      vbim_ref_blend16_rect(dst, 32, src, 32, 8, 4, 0, 0, (int)fix, strcmp(mode, "clamp") == 0, dthe, 0);
    } else {
      vbim_ref_blend_span(dst, src, 32, (int)fix, strcmp(mode, "clamp") == 0, 0);
    }
    to_hex(dst, 128, got);
    sprintf(key, "%s/result", base);
    expect(f, key, find(f, key), got);
  }
}

int main(int argc, char** argv) {
  static const char* names[] = {"frame_hash.txt", "blend.txt", "idct.txt", "csc.txt", "draw.txt"};
  static void (*const checks[])(vfile*) = {check_frame_hash, check_blend, check_idct, check_csc, check_draw};
  int k, status = 0;
  if (argc != 2) {
    fprintf(stderr, "usage: vbim_ref_check DIR\n");
    return 2;
  }
  for (k = 0; k < 5; ++k) {
    vfile f;
    load(argv[1], names[k], &f);
    checks[k](&f);
    printf("%s: %lu of %lu entries match\n", names[k], (unsigned long)(f.checked - f.failed), (unsigned long)f.checked);
    if (f.failed > 0 || f.checked == 0) status = 1;
    release(&f);
  }
  return status;
}
