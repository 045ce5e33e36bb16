#pragma once
/// @file
/// ISO 8608 random road: a deterministic 2-D grid of heights (an OpenCRG grid, model/road/
/// crg_data.h, evaluated by CrgSurface) whose every long section has the displacement PSD of a
/// road class, and whose long sections are correlated across the width by a stated coherence.
///
/// PSD (ISO 8608:2016, eq. for w = 2): G_d(n) = G_d(n0) (n / n0)^-2, n0 = 0.1 cycles/m, G_d(n0)
/// the geometric mean of the class band (A 16, B 64, C 256, D 1024, E 4096 x 1e-6 m^3), applied
/// from ISO 8608's lowest spatial frequency 0.011 cycles/m up to the grid's Nyquist frequency.
///
/// Coherence across the width: the isotropic road (Kamash and Robson, "The application of
/// isotropy in road surface modelling", J. Sound Vib. 57(1), 1978; Bogsjo, Podgorski and
/// Rychlik, Vehicle System Dynamics 50, 2012): an isotropic 2-D surface whose profiles along any
/// line have G_d(n) = C n^-2 has the 2-D spectrum (C/2) kappa^-3, and the cross spectrum of two
/// parallel profiles a distance d apart is G_d(n) gamma(n, d) with
///     gamma(n, d) = 2 pi n d K_1(2 pi n d)        (K_1: modified Bessel function, 2nd kind),
/// real, 1 at d = 0, falling with n d (0.5 at n d = 0.20): long waves lift both tracks alike
/// (heave), short ones differ (roll).
///
/// Generation (spectral, exact in the model's statistics on the grid): for each frequency n_k =
/// k / (N dx) of an N-point FFT the nv long sections get complex amplitudes
///     c_k = sqrt(G_d(n_k) dn) L_k (xi + i eta),    L_k L_k^T = [gamma(n_k, |v_j - v_l|)]
/// (xi, eta independent standard normal vectors from a seeded mt19937_64, Box-Muller), and each
/// long section is z_j(x_m) = Re sum_k c_k,j exp(i 2 pi k m / N), m = 0..nu-1. The heights fade in
/// and out linearly over the first and last `fade_m` (OpenCRG's BORDER_SMOOTH_UBEG/UEND), so that
/// the road joins the plane z = 0 beyond its ends. Load time only (allocates).

#include <cstdint>

#include "model/road/crg_data.h"

namespace rig::model::road {

struct Iso8608Params {
  char road_class = 'C';  ///< 'A'..'E'
  std::uint64_t seed = 1;
  double length_m = 1000;   ///< along x, from x = 0 (the reference line starts at the origin)
  double width_m = 4;       ///< across, centred on the reference line
  double spacing_m = 0.05;  ///< grid spacing along and across
  double fade_m = 5;        ///< linear fade-in / fade-out at the ends
};

/// ISO 8608's reference spatial frequency n0 [cycles/m] and lowest frequency applied.
inline constexpr double kIso8608N0 = 0.1;
inline constexpr double kIso8608MinFrequency = 0.011;

/// G_d(n0) [m^3] of a class: the geometric mean of its band; 0 for an unknown class.
double iso8608_class_gd(char road_class);
/// The class band [lower, upper) of G_d(n0) [m^3] (class A: from 0).
void iso8608_class_band(char road_class, double& lower, double& upper);
/// The isotropic coherence gamma(n, d) = 2 pi n d K_1(2 pi n d) of two profiles d [m] apart at
/// spatial frequency n [cycles/m].
double iso8608_coherence(double n_cpm, double distance_m);

/// The road as an OpenCRG grid: straight reference line from (0, 0) along +x, v centred,
/// BORDER_MODE keep-last, the fades as BORDER_SMOOTH_UBEG/UEND.
CrgData generate_iso8608(const Iso8608Params& params);

}  // namespace rig::model::road
