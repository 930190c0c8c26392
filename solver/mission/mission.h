#pragma once
// A mission's measurements as flat arrays on one time grid (structure of arrays).
// Built and validated by io/ (and by the simulator); solver/ only reads it.
//
// Invariants (checked by io/ before a Mission reaches the solver):
//  - nav arrays all have the length of `time`, which is strictly increasing;
//  - every value is finite; marks lie within [time.front(), time.back()];
//  - the optional half-width arrays are empty or have the length of `time`;
//  - truth arrays are empty or complete.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "solver/mission/sensor_model.h"

namespace gesmi {

/// Local NED frame origin (WGS84 degrees).
struct GeoOrigin {
  double latitude = 0.0;
  double longitude = 0.0;
};

/// How an import filled a channel's samples that have no reading of their own
/// (io/imports/nav_grid.h): by which model key ("surface_max_speed" for the DVL
/// bridged by the speed at the surface, "max_depth_rate" for depth enclosed between
/// its readings, ...), and how many samples before its first reading, between its
/// readings and after its last. `key` empty: none (the channel's half-widths, if any,
/// are the log's own).
struct ChannelFill {
  std::string key;
  std::size_t before = 0, between = 0, after = 0;
  double first_reading = 0.0, last_reading = 0.0;  // s
  std::size_t samples() const { return before + between + after; }
};

/// Per-sample half-widths that override the model's bounds (GESMI text logs give them;
/// an import makes them where it fills samples without a reading).
struct NavHalfWidths {
  std::vector<double> roll, pitch, heading, vx, vy, vz, depth, altitude;
  /// Per channel, in nav_channels() order: what the import filled.
  std::array<ChannelFill, 8> fill;
  /// Whether `fill` is known (false for mission files older than format 4, which did
  /// not record it: half-widths there may be the log's own or the import's).
  bool fill_recorded = true;
  bool empty() const { return roll.empty(); }
};

/// Mine indices are 0..K-1 with K <= kMaxMines (a mark's candidate mines are the
/// bits of a 64-bit word).
inline constexpr int kMaxMines = 64;

struct Mission;

/// A navigation channel that may carry per-sample half-widths: its name (the HDF5
/// dataset /nav/half_widths/<name>, the CSV column <name>_halfwidth), its readings
/// and its half-widths in a Mission.
struct NavChannel {
  std::string_view name;
  std::vector<double> Mission::*readings;
  std::vector<double> NavHalfWidths::*half_widths;
};

/// The step k (from time[k] to time[k + 1]) of a gap in the readings: the longest step
/// when it is more than twice the median step, else nullopt. The step model 'sample'
/// cannot cross one soundly (docs/model.md, "Gaps").
std::optional<std::size_t> longest_gap(const std::vector<double>& time);

/// The eight channels, in the navigation CSV's column order.
const std::array<NavChannel, 8>& nav_channels();
/// The channel of that name (one of nav_channels()).
const NavChannel& nav_channel(std::string_view name);
/// The model's bound on a reading `value` of nav_channels()[channel], rounded up as the
/// solver computes it (SensorBoxes): the per-sample half-width an importer writes.
double model_half_width(const SensorModel& model, std::size_t channel, double value);

struct Mission {
  // Navigation, N samples.
  std::vector<double> time;                  // s, strictly increasing
  std::vector<double> roll, pitch, heading;  // rad (gyrocompass)
  std::vector<double> vx, vy, vz;            // m/s, DVL, body frame (x forward, y starboard, z down)
  std::vector<double> altitude;              // m above the sea floor (DVL)
  std::vector<double> depth;                 // m (barometer)
  NavHalfWidths half_widths;                 // optional overrides

  // GPS fixes, G samples.
  std::vector<double> gps_time;       // s
  std::vector<double> gps_longitude;  // deg WGS84
  std::vector<double> gps_latitude;   // deg WGS84
  // Optional per-fix metric bounds given by the source (a GESMI text log's x/y
  // half-widths, or a GPS CSV's north/east_halfwidth columns), replacing the model's
  // GPS bounds for that fix: both empty, or both of length G.
  std::vector<double> gps_given_north_halfwidth, gps_given_east_halfwidth;  // m
  // Set when a --config (or Python) changed the model's GPS bounds of a mission whose
  // fixes carry their own: each fix's box is then the larger of its own half-widths
  // and the model's bounds, in solve and kalman alike (docs/formats.md, "GPS bounds").
  bool gps_model_floor = false;
  // The same fixes in the local frame, filled by io/ (geodesy): centre and
  // half-width of the box that contains the true position (the given bound, or else
  // the larger of the model's degree bound in metres and its metric bound, or the
  // larger of both with gps_model_floor; plus the conversion error).
  std::vector<double> gps_north, gps_east;                     // m
  std::vector<double> gps_north_halfwidth, gps_east_halfwidth;  // m
  // Largest angle between true north and the local frame's north axis (meridian
  // convergence) anywhere in the frame's zone (rad), added to the heading bound; the
  // solve narrows it per sample over the tube (solver/network/frame/frame_margins.h).
  double heading_frame_margin = 0.0;
  // The local frame's scale against the sea surface along any path within the frame's
  // zone (solver/mission/frame_scale.h), filled by io/: a step's north and east
  // increments widen by it times the step's integrated |w_north| + |w_east|; the solve
  // narrows it per sample like the heading's (solver/network/frame/frame_margins.h).
  double frame_scale_margin = 0.0;
  // How much faster than the robot the surface point above it moves, at the deepest
  // the sonar's geometry reaches (docs/model.md, "The local frame's scale"), filled by
  // io/: each DVL component's bound grows by it times the box's largest |vx| + |vy| +
  // |vz|, and a mark's horizontal offset by it times the range. Both margins are zero
  // for a mission made in a flat world (the simulator's, before it is written).
  double depth_scale_margin = 0.0;

  // Mark table, M detections.
  std::vector<double> mark_time;        // s
  std::vector<std::int32_t> mark_mine;  // mine index, -1 when not associated
  std::vector<double> mark_range;       // slant range, m
  std::vector<std::int32_t> mark_side;  // +1 starboard, -1 port

  // Number of mines K (mine indices are 0..K-1).
  int mine_count = 0;

  // What unit conversions at import added to the model's bounds (rad; m/s for the DVL:
  // io/imports/import_mapped_nav.h), kept so that a --config replacing one of those
  // bounds adds it again.
  struct ConversionMargins {
    double roll = 0.0, pitch = 0.0, heading = 0.0, dvl = 0.0;
  } conversion_margins;

  GeoOrigin origin;
  // UTC time of t = 0 in whole seconds since 1970-01-01 (Unix time), when the log gave
  // absolute times or the import was told it (--epoch).
  std::optional<std::int64_t> epoch;
  SensorModel model;

  // Ground truth of simulated missions (empty otherwise).
  std::vector<double> truth_x, truth_y, truth_z;  // local NED, m, N samples
  std::vector<double> truth_mines;                // K×3 row-major, local NED, m
  std::vector<double> truth_missed_marks;         // X×3 row-major: time, mine, range of dropped detections
  std::vector<std::int32_t> truth_marks_outlier;  // M: 1 for a corrupted mark
  std::vector<std::int32_t> truth_marks_mine;     // M: the mine each mark really is
  std::vector<std::int32_t> truth_gps_outlier;    // G: 1 for a corrupted fix

  std::size_t size() const { return time.size(); }
  std::size_t mark_count() const { return mark_time.size(); }
  bool has_truth() const { return !truth_x.empty(); }
};

}  // namespace gesmi
