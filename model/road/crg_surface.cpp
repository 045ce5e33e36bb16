#include "model/road/crg_surface.h"

#include <algorithm>
#include <cmath>

namespace rig::model::road {
namespace {

/// Equally spaced long sections (to rounding): the cell follows by division.
bool equally_spaced(const std::vector<double>& v) {
  const double step = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
  const double tolerance = 1e-9 * std::max(1.0, v.back() - v.front());
  for (std::size_t j = 0; j < v.size(); ++j) {
    if (std::abs(v[j] - (v.front() + static_cast<double>(j) * step)) > tolerance) return false;
  }
  return true;
}

/// The reference line's height per cross section: z_ref,i = z_ref,i-1 + slope_i du (entry 0 of
/// the slope channel unused, as the heading's), from START_Z; a given END_Z takes the closure
/// error, spread linearly.
std::vector<double> reference_heights(const CrgData& d) {
  const std::size_t n = d.nu();
  std::vector<double> z(n, d.start_z_m);
  for (std::size_t i = 1; i < n; ++i) {
    const double slope = d.slope.empty() ? d.start_slope : d.slope[i];
    z[i] = z[i - 1] + d.mods.scale_slope * slope * d.u_increment_m;
  }
  if (std::isfinite(d.end_z_m) && n > 1) {
    const double error = d.end_z_m - z[n - 1];
    for (std::size_t i = 1; i < n; ++i)
      z[i] += error * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  return z;
}

}  // namespace

CrgSurface::CrgSurface(const CrgData& data, const Placement& placement)
    : line_(data),
      options_(data.options),
      u_first_m_(data.u_first_m),
      u_last_m_(data.u_last_m()),
      du_m_(data.u_increment_m),
      v_(data.v_m),
      v_equal_(equally_spaced(data.v_m)),
      dv_m_((data.v_m.back() - data.v_m.front()) / static_cast<double>(data.nv() - 1)),
      nv_(static_cast<int>(data.nv())),
      nu_(static_cast<int>(data.nu())),
      z_ref_(reference_heights(data)),
      bank_(data.nu(), data.start_bank) {
  inv_du_ = 1.0 / du_m_;
  smoothing_ = options_.smooth_ubeg_m > 0 || options_.smooth_uend_m > 0;
  inv_dv_ = 1.0 / dv_m_;
  for (std::size_t j = 0; j + 1 < v_.size(); ++j) inv_dv_cell_.push_back(1.0 / (v_[j + 1] - v_[j]));
  if (!data.banking.empty()) bank_ = data.banking;
  for (double& b : bank_) b *= data.mods.scale_banking;
  fill_nans(data);
  place(data, placement);
}

void CrgSurface::fill_nans(const CrgData& data) {
  z_ = data.z_m;
  const auto scale = static_cast<float>(data.mods.scale_z_grid);
  for (float& z : z_) z *= scale;
  const auto offset = static_cast<float>(data.mods.nan_offset_m);
  const bool keep = data.mods.nan_mode == CrgNanMode::kKeepLast;
  const auto nv = static_cast<std::size_t>(nv_);
  for (std::size_t i = 0; i < static_cast<std::size_t>(nu_); ++i) {
    float* row = &z_[i * nv];
    std::size_t lo = 0;
    while (lo < nv && std::isnan(row[lo])) ++lo;
    std::size_t hi = nv;
    while (hi > lo && std::isnan(row[hi - 1])) --hi;
    if (lo == nv) continue;  // the loaders refuse an all-NaN cross section
    for (std::size_t j = 0; j < lo; ++j) row[j] = keep ? row[lo] + offset : offset;
    for (std::size_t j = hi; j < nv; ++j) row[j] = keep ? row[hi - 1] + offset : offset;
  }
}

void CrgSurface::place(const CrgData& data, const Placement& placement) {
  const Placement& p = placement.given ? placement : data.mods.refpoint;
  if (!p.given) return;  // where the file puts it
  const double u = std::isnan(p.u_m) ? u_first_m_ : p.u_m;
  line_.point(u, p.v_m, ref_x_m_, ref_y_m_);
  int cell = -1;
  const double z_at = at_uv(u, p.v_m, cell).z_m;
  const double rotation = p.heading_rad - line_.heading_rad(u);
  cos_ = std::cos(rotation);
  sin_ = std::sin(rotation);
  tx_m_ = p.x_m;
  ty_m_ = p.y_m;
  dz_m_ = p.z_m - z_at;
}

SurfaceHeight CrgSurface::height(double x_m, double y_m, SurfaceHint& hint) const noexcept {
  // road frame -> the file's frame: p_file = R(-rotation) (p - t) + p_ref
  const double qx = x_m - tx_m_;
  const double qy = y_m - ty_m_;
  const double fx = cos_ * qx + sin_ * qy + ref_x_m_;
  const double fy = -sin_ * qx + cos_ * qy + ref_y_m_;
  const CrgStation s = line_.locate(fx, fy, hint.i);
  const UvHeight h = evaluate(u_axis(s), v_axis(s.v_m, hint.j));
  const double gx = h.dz_du * s.du_dx + h.dz_dv * s.dv_dx;
  const double gy = h.dz_du * s.du_dy + h.dz_dv * s.dv_dy;
  // the gradient back into the road frame: R(rotation) g
  return {h.absolute ? h.z_m : h.z_m + dz_m_, cos_ * gx - sin_ * gy, sin_ * gx + cos_ * gy};
}

void CrgSurface::world_point(double u_m, double v_m, double& x_m, double& y_m) const noexcept {
  double fx = 0;
  double fy = 0;
  line_.point(u_m, v_m, fx, fy);
  fx -= ref_x_m_;
  fy -= ref_y_m_;
  x_m = cos_ * fx - sin_ * fy + tx_m_;
  y_m = sin_ * fx + cos_ * fy + ty_m_;
}

CrgSurface::AxisPoint CrgSurface::u_axis(const CrgStation& s) const noexcept {
  if (s.segment < 0) return u_axis(s.u_m);
  AxisPoint p;
  p.cell = s.segment;
  p.frac = s.fraction;
  p.dfrac = inv_du_;
  p.mapped = s.u_m;
  return p;
}

CrgSurface::AxisPoint CrgSurface::u_axis(double u_m) const noexcept {
  AxisPoint p;
  p.mapped = u_m;
  const double span = u_last_m_ - u_first_m_;
  if (u_m < u_first_m_ || u_m > u_last_m_) {
    if (options_.border_u == CrgBorderMode::kRepeat) {
      double t = std::fmod(u_m - u_first_m_, span);
      if (t < 0) t += span;
      p.mapped = u_first_m_ + t;
    } else if (options_.border_u == CrgBorderMode::kReflect) {
      double t = std::fmod(std::abs(u_m - u_first_m_), 2 * span);
      p.dmapped = u_m >= u_first_m_ ? 1.0 : -1.0;
      if (t > span) {
        t = 2 * span - t;
        p.dmapped = -p.dmapped;
      }
      p.mapped = u_first_m_ + t;
    } else {  // keep last, zero: held at the end
      p.outside = true;
      p.mapped = std::clamp(u_m, u_first_m_, u_last_m_);
      p.dmapped = 0;
    }
  }
  const double t = (p.mapped - u_first_m_) * inv_du_;
  p.cell = std::clamp(static_cast<int>(t), 0, nu_ - 2);  // t >= 0: truncation is floor
  p.frac = std::clamp(t - p.cell, 0.0, 1.0);
  p.dfrac = p.dmapped * inv_du_;
  return p;
}

int CrgSurface::v_cell_of(double v_m, int v_cell) const noexcept {
  if (v_equal_) return std::clamp(static_cast<int>((v_m - v_.front()) * inv_dv_), 0, nv_ - 2);
  if (v_cell < 0 || v_cell > nv_ - 2) {
    const auto it = std::upper_bound(v_.begin() + 1, v_.end() - 1, v_m);
    return static_cast<int>(it - v_.begin()) - 1;
  }
  while (v_cell > 0 && v_m < v_[static_cast<std::size_t>(v_cell)]) --v_cell;
  while (v_cell < nv_ - 2 && v_m > v_[static_cast<std::size_t>(v_cell) + 1]) ++v_cell;
  return v_cell;
}

CrgSurface::AxisPoint CrgSurface::v_axis(double v_m, int& v_cell) const noexcept {
  AxisPoint p;
  p.mapped = v_m;
  const double first = v_.front();
  const double last = v_.back();
  if (v_equal_ && v_m >= first && v_m <= last) {  // the usual case: on the grid, equal cells
    const double t = (v_m - first) * inv_dv_;
    v_cell = std::min(static_cast<int>(t), nv_ - 2);
    p.cell = v_cell;
    p.frac = std::min(t - v_cell, 1.0);
    p.dfrac = inv_dv_;
    return p;
  }
  const double span = last - first;
  if (v_m < first || v_m > last) {
    if (options_.border_v == CrgBorderMode::kRepeat) {
      double t = std::fmod(v_m - first, span);
      if (t < 0) t += span;
      p.mapped = first + t;
    } else if (options_.border_v == CrgBorderMode::kReflect) {
      double t = std::fmod(std::abs(v_m - first), 2 * span);
      p.dmapped = v_m >= first ? 1.0 : -1.0;
      if (t > span) {
        t = 2 * span - t;
        p.dmapped = -p.dmapped;
      }
      p.mapped = first + t;
    } else {
      p.outside = true;
      p.mapped = std::clamp(v_m, first, last);
      p.dmapped = 0;
    }
  }
  v_cell = v_cell_of(p.mapped, v_cell);
  p.cell = v_cell;
  const double inv_width = inv_dv_cell_[static_cast<std::size_t>(v_cell)];
  p.frac = std::clamp((p.mapped - v_[static_cast<std::size_t>(v_cell)]) * inv_width, 0.0, 1.0);
  p.dfrac = p.dmapped * inv_width;
  return p;
}

void CrgSurface::add_reference_terms(const AxisPoint& u, const AxisPoint& v,
                                     UvHeight& h) const noexcept {
  const auto i = static_cast<std::size_t>(u.cell);
  const double dz_ref = z_ref_[i + 1] - z_ref_[i];
  const double dbank = bank_[i + 1] - bank_[i];
  const double bank = bank_[i] + u.frac * dbank;
  // banking acts on v clamped to the grid's width (v.mapped is, v.dmapped is 0 where held)
  h.z_m += z_ref_[i] + u.frac * dz_ref + bank * v.mapped;
  h.dz_du += (dz_ref + dbank * v.mapped) * u.dfrac;
  h.dz_dv += bank * v.dmapped;
}

void CrgSurface::smooth(const AxisPoint& u, UvHeight& h) const noexcept {
  // BORDER_SMOOTH_UBEG/UEND: z = base + (z - base) s, s rising linearly over the zone
  auto fade = [&](double distance_m, double zone_m, double base_m, double sign) {
    if (!(zone_m > 0) || distance_m > zone_m) return;
    const double s = distance_m / zone_m;
    h.dz_du = (h.z_m - base_m) * sign * u.dmapped / zone_m + s * h.dz_du;
    h.dz_dv *= s;
    h.z_m = base_m + (h.z_m - base_m) * s;
  };
  fade(u.mapped - u_first_m_, options_.smooth_ubeg_m, z_ref_.front(), 1.0);
  fade(u_last_m_ - u.mapped, options_.smooth_uend_m, z_ref_.back(), -1.0);
}

CrgSurface::UvHeight CrgSurface::at_uv(double u_m, double v_m, int& v_cell) const noexcept {
  return evaluate(u_axis(u_m), v_axis(v_m, v_cell));
}

CrgSurface::UvHeight CrgSurface::evaluate(const AxisPoint& u, const AxisPoint& v) const noexcept {
  UvHeight h;
  const double offset_m = (u.outside ? options_.border_offset_u_m : 0.0) +
                          (v.outside ? options_.border_offset_v_m : 0.0);
  if ((u.outside && options_.border_u == CrgBorderMode::kZero) ||
      (v.outside && options_.border_v == CrgBorderMode::kZero)) {
    h.z_m = offset_m;  // BORDER_MODE 1: the offset alone
    h.absolute = true;
    return h;
  }
  // bilinear in the cell (OpenCRG's crgEvaluv2z)
  const float* z0 = &z_[static_cast<std::size_t>(u.cell) * static_cast<std::size_t>(nv_) +
                        static_cast<std::size_t>(v.cell)];
  const float* z1 = z0 + nv_;
  const double z00 = z0[0];
  const double along_u = z1[0] - z00;
  const double along_v = z0[1] - z00;
  const double twist = static_cast<double>(z1[1]) - z1[0] - z0[1] + z00;
  h.z_m = z00 + along_u * u.frac + (along_v + twist * u.frac) * v.frac;
  h.dz_du = (along_u + twist * v.frac) * u.dfrac;
  h.dz_dv = (along_v + twist * u.frac) * v.dfrac;
  add_reference_terms(u, v, h);
  h.z_m += offset_m;
  if (smoothing_) smooth(u, h);
  return h;
}

}  // namespace rig::model::road
