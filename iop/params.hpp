// Every timing constant of the IOP side (drive, stream ring, SIF), as plain settings structs with
// the defaults explained in docs/hardware.md (drive and ring) and docs/hardware.md#model-defaults.
// describeParams registers them in a ParamTable under the prefixes "drive.", "ring." and "sif.", each
// with its unit and its source; docs/timing/iop.md lists them.
#pragma once

#include <cstdint>
#include <string>

#include "iop/sector_source.hpp"
#include "runtime/param_table.hpp"

namespace vbim::iop {

struct DriveParams {
  // Spindle: "cav" (SCECdSpinMax/SpinStm: DVD 4x CAV, rate grows with radius) or "clv" (SpinDvd 1.6x).
  std::string spindle = "cav";
  std::int64_t cav_outer_sectors_per_s = 2700;  // 675 sectors/s at 1x, x4 (P-CDVDi)
  std::int64_t cav_inner_percent = 40;          // f = 0.40 + 0.60 * LSN / layer (P-CDVD)
  std::int64_t clv_sectors_per_s = 1080;        // 1.6x (P-CDVD)
  std::int64_t layer_sectors = 2'298'496;       // single-layer DVD (P-CDVD)
  std::int64_t contiguous_window_sectors = 16;  // forward jumps below this are no seek (P-CDVDi)
  std::int64_t fast_seek_window_sectors = 14'764;
  std::int64_t fast_seek_us = 30'000;
  std::int64_t full_seek_us = 100'000;
  std::int64_t revolution_us = 16'000;  // latency uniform in [0, 1 rev): 8 ms mean
  std::int64_t spin_up_ms = 333;
  bool initially_spinning = false;
  std::int64_t read_ahead_sectors = 16;
  // IOP DMA channel 3 moves the sector's bytes at 12 IOP cycles per 32-bit word (P-CDVD). The stream
  // driver reads with sceCdRE and mode.datapattern = SCECdSecS2048 (SDK-ST), so each sector delivers
  // its 2,048 bytes of user data: (2048 / 4) x 12 = 6,144. The 2,064-byte raw sector is only what
  // sceCdReadDVDV (N command 0x08) returns, which no modelled path issues.
  std::int64_t dma_iop_cycles_per_sector = static_cast<std::int64_t>(kSectorBytes) / 4 * 12;
  std::int64_t retry_count = 0;       // sceCdRMode.trycount: drive retries per sector; 0 = 256
  std::int64_t sector_error_ppm = 0;  // random per-sector read errors per million reads
};

struct RingParams {
  std::int64_t bufmax_sectors = 160;            // sceCdStInit bufmax: 320 KiB of IOP RAM
  std::int64_t bankmax = 5;                     // sceCdStInit bankmax (32-sector banks)
  std::int64_t repoll_ms = 8;                   // "read Full" alarm 0x48000 IOP cycles (SDK-ST)
  std::int64_t issue_retry_ms = 200;            // alarm after a failed sceCdRE, 0x708000 IOP cycles (SDK-ST)
  std::int64_t read_timeout_ms = 5'000;         // g_cdvdman_stream_timeout default (SDK-CD)
  std::int64_t first_read_timeout_ms = 15'000;  // 0x20F58000 IOP cycles (SDK-ST)
  std::int64_t read_error_retries = 3;          // on 0x30 / 0x01 (SDK-ST)
  std::int64_t runup_step_sectors = 16;         // retries start 32, 16, 0 sectors early (SDK-ST)
};

struct SifParams {
  std::int64_t bandwidth_bytes_per_s = 20'000'000;  // assumption (docs/hardware.md#sif-rate)
  std::int64_t setup_us = 30;                       // assumption, per sceSifSetDma chunk
};

struct IopParams {
  DriveParams drive;
  RingParams ring;
  SifParams sif;
};

void describeParams(ParamTable& t, DriveParams& p);
void describeParams(ParamTable& t, RingParams& p);
void describeParams(ParamTable& t, SifParams& p);
void describeParams(ParamTable& t, IopParams& p);

// Checks relations between parameters that single ranges cannot (e.g. bufmax >= bankmax).
// Throws ConfigError naming the keys.
void validate(const IopParams& p);

}  // namespace vbim::iop
