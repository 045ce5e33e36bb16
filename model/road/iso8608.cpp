#include "model/road/iso8608.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <unsupported/Eigen/FFT>
#include <vector>

namespace rig::model::road {
namespace {

using Complex = std::complex<double>;

/// A coherence factor serves the frequencies up to 0.5 % above the one it was computed at: the
/// coherence is then that of a frequency at most 0.5 % lower, off by at most 0.0025 (|d gamma /
/// d ln x| = x^2 K_0(x) <= 0.48), and the generation factors some 1400 matrices, not one per FFT
/// frequency.
constexpr double kFactorReuse = 1.005;

/// Independent standard normal numbers from a seeded mt19937_64 (whose sequence the C++
/// standard fixes), by Box-Muller: the same seed gives the same road everywhere.
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : engine_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    // u1 in (0, 1]: 53 random bits, never 0
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2 * std::numbers::pi * u2);
    has_spare_ = true;
    return r * std::cos(2 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

std::size_t next_power_of_two(std::size_t n) {
  std::size_t p = 1;
  while (p < n) p <<= 1;
  return p;
}

/// The lower factor of the coherence matrix [gamma(n, |v_j - v_l|)] of equally spaced long
/// sections (with a relative 1e-9 on the diagonal: at long waves the matrix tends to all ones,
/// singular; the jitter adds an independent part of relative variance 1e-9).
Eigen::MatrixXd coherence_factor(double n_cpm, double spacing_m, int nv) {
  Eigen::VectorXd by_distance(nv);
  for (int d = 0; d < nv; ++d) by_distance(d) = iso8608_coherence(n_cpm, d * spacing_m);
  Eigen::MatrixXd c(nv, nv);
  for (int j = 0; j < nv; ++j) {
    for (int l = 0; l < nv; ++l) c(j, l) = by_distance(std::abs(j - l));
  }
  c.diagonal().array() += 1e-9;
  return c.llt().matrixL();
}

/// The complex amplitudes c_k,j of every long section j at every frequency k (spectra[j][k]),
/// kept in single precision (the heights are float32; half the memory of a long road).
std::vector<std::vector<std::complex<float>>> spectra(const Iso8608Params& p, std::size_t n_fft,
                                                      int nv) {
  std::vector<std::vector<std::complex<float>>> s(static_cast<std::size_t>(nv),
                                                  std::vector<std::complex<float>>(n_fft));
  Normal normal(p.seed);
  const double dn = 1.0 / (static_cast<double>(n_fft) * p.spacing_m);
  const double gd0 = iso8608_class_gd(p.road_class);
  Eigen::VectorXd xi(nv);
  Eigen::VectorXd eta(nv);
  Eigen::MatrixXd l;
  double factored_at = 0;  // the frequency l was factored at
  for (std::size_t k = 1; k < n_fft / 2; ++k) {
    const double n = static_cast<double>(k) * dn;
    for (int j = 0; j < nv; ++j) {  // drawn for every k: a frequency band's draws never shift
      xi(j) = normal.next();
      eta(j) = normal.next();
    }
    if (n < kIso8608MinFrequency) continue;
    const double amplitude = std::sqrt(gd0 * std::pow(kIso8608N0 / n, 2) * dn);
    if (n > factored_at * kFactorReuse) {
      l = coherence_factor(n, p.spacing_m, nv);
      factored_at = n;
    }
    const Eigen::VectorXd re = l * xi;
    const Eigen::VectorXd im = l * eta;
    for (int j = 0; j < nv; ++j) {
      s[static_cast<std::size_t>(j)][k] = std::complex<float>(
          static_cast<float>(amplitude * re(j)), static_cast<float>(amplitude * im(j)));
    }
  }
  return s;
}

}  // namespace

double iso8608_class_gd(char road_class) {
  if (road_class < 'A' || road_class > 'E') return 0;
  // A 16e-6, each class 4 times the one before (ISO 8608 Table 1, n0 = 0.1 cycles/m)
  return 16e-6 * std::pow(4.0, road_class - 'A');
}

void iso8608_class_band(char road_class, double& lower, double& upper) {
  const double mean = iso8608_class_gd(road_class);
  lower = road_class == 'A' ? 0.0 : mean / 2;
  upper = mean * 2;
}

double iso8608_coherence(double n_cpm, double distance_m) {
  const double x = 2 * std::numbers::pi * std::abs(n_cpm * distance_m);
  if (x < 1e-300) return 1.0;
  if (x > 700) return 0.0;  // K_1 underflows; x K_1(x) ~ sqrt(pi x / 2) e^-x
  return x * std::cyl_bessel_k(1.0, x);
}

CrgData generate_iso8608(const Iso8608Params& p) {
  const auto nu = static_cast<std::size_t>(std::llround(p.length_m / p.spacing_m)) + 1;
  const int nv = static_cast<int>(std::llround(p.width_m / p.spacing_m)) + 1;
  const std::size_t n_fft = next_power_of_two(nu);
  CrgData d;
  d.u_first_m = 0;
  d.u_increment_m = p.spacing_m;
  d.v_m.resize(static_cast<std::size_t>(nv));
  for (int j = 0; j < nv; ++j)
    d.v_m[static_cast<std::size_t>(j)] = (j - (nv - 1) / 2.0) * p.spacing_m;
  d.z_m.resize(nu * static_cast<std::size_t>(nv));
  const std::vector<std::vector<std::complex<float>>> s = spectra(p, n_fft, nv);
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::Unscaled);
  std::vector<Complex> c(n_fft);
  std::vector<Complex> z(n_fft);
  for (int j = 0; j < nv; ++j) {
    const auto& line = s[static_cast<std::size_t>(j)];
    std::copy(line.begin(), line.end(), c.begin());
    fft.inv(z, c);  // sum_k c_k exp(+i 2 pi k m / N)
    for (std::size_t i = 0; i < nu; ++i)
      d.z_m[i * static_cast<std::size_t>(nv) + static_cast<std::size_t>(j)] =
          static_cast<float>(z[i].real());
  }
  d.options.smooth_ubeg_m = p.fade_m;
  d.options.smooth_uend_m = p.fade_m;
  return d;
}

}  // namespace rig::model::road
