#include "rig/paper/spring_reference.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace rig::paper {

using model::paper::CoupledPendulumsParams;
using model::paper::rod_geometry;

struct SpringReference::Impl {
  CoupledPendulumsParams p;
  SpringReferenceParams sp;
  double rod_length_m = 0;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNMatrix a = nullptr;
  SUNLinearSolver ls = nullptr;
  void* cvode = nullptr;
  double t = 0;

  // T = c (l - s) + d l'
  [[nodiscard]] double rod_force(const double* s) const {
    const auto r = rod_geometry(p, s[0], s[1]);
    const double l_dot = r.dl_dphi1_m * s[2] + r.dl_dphi2_m * s[3];
    return sp.stiffness_npm * (r.length_m - rod_length_m) + sp.damping_nspm * l_dot;
  }

  static int rhs(sunrealtype, N_Vector y, N_Vector ydot, void* user) {
    const auto* self = static_cast<const Impl*>(user);
    const double* s = N_VGetArrayPointer(y);
    double* d = N_VGetArrayPointer(ydot);
    const CoupledPendulumsParams& p = self->p;
    const auto r = rod_geometry(p, s[0], s[1]);
    const double force = self->rod_force(s);
    d[0] = s[2];
    d[1] = s[3];
    d[2] = (-p.mass1_kg * p.gravity_mps2 * p.length1_m * std::sin(s[0]) - force * r.dl_dphi1_m) /
           (p.mass1_kg * p.length1_m * p.length1_m);
    d[3] = (-p.mass2_kg * p.gravity_mps2 * p.length2_m * std::sin(s[1]) - force * r.dl_dphi2_m) /
           (p.mass2_kg * p.length2_m * p.length2_m);
    return 0;
  }

  ~Impl() {
    if (cvode != nullptr) CVodeFree(&cvode);
    if (ls != nullptr) SUNLinSolFree(ls);
    if (a != nullptr) SUNMatDestroy(a);
    if (y != nullptr) N_VDestroy(y);
    if (ctx != nullptr) SUNContext_Free(&ctx);
  }
};

namespace {
void check(int flag, const char* what) {
  if (flag < 0)
    throw std::runtime_error(std::string("CVODE: ") + what + " failed, flag " +
                             std::to_string(flag));
}
}  // namespace

SpringReference::SpringReference(const CoupledPendulumsParams& pendulums,
                                 const SpringReferenceParams& params)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.p = pendulums;
  m.sp = params;
  m.rod_length_m = model::paper::rod_length_m(pendulums);
  check(SUNContext_Create(nullptr, &m.ctx), "SUNContext_Create");
  m.y = N_VNew_Serial(4, m.ctx);
  if (m.y == nullptr) throw std::runtime_error("CVODE: N_VNew_Serial failed");
  double* s = N_VGetArrayPointer(m.y);
  s[0] = pendulums.phi1_0_rad;
  s[1] = pendulums.phi2_0_rad;
  s[2] = 0.0;
  s[3] = 0.0;
  m.cvode = CVodeCreate(CV_BDF, m.ctx);
  if (m.cvode == nullptr) throw std::runtime_error("CVODE: CVodeCreate failed");
  check(CVodeInit(m.cvode, &Impl::rhs, 0.0, m.y), "CVodeInit");
  check(CVodeSetUserData(m.cvode, &m), "CVodeSetUserData");
  check(CVodeSStolerances(m.cvode, params.relative_tolerance, params.absolute_tolerance),
        "CVodeSStolerances");
  m.a = SUNDenseMatrix(4, 4, m.ctx);
  m.ls = SUNLinSol_Dense(m.y, m.a, m.ctx);
  check(CVodeSetLinearSolver(m.cvode, m.ls, m.a), "CVodeSetLinearSolver");
  check(CVodeSetMaxNumSteps(m.cvode, 1000000), "CVodeSetMaxNumSteps");
}

SpringReference::~SpringReference() = default;

void SpringReference::advance_to(double t_s) {
  double t_reached = impl_->t;
  check(CVode(impl_->cvode, t_s, impl_->y, &t_reached, CV_NORMAL), "CVode");
  impl_->t = t_reached;
}

double SpringReference::time_s() const noexcept { return impl_->t; }
double SpringReference::phi1_rad() const noexcept { return N_VGetArrayPointer(impl_->y)[0]; }
double SpringReference::phi2_rad() const noexcept { return N_VGetArrayPointer(impl_->y)[1]; }
double SpringReference::rod_force_n() const noexcept {
  return impl_->rod_force(N_VGetArrayPointer(impl_->y));
}
double SpringReference::constraint_violation_m() const noexcept {
  const double* s = N_VGetArrayPointer(impl_->y);
  return rod_geometry(impl_->p, s[0], s[1]).length_m - impl_->rod_length_m;
}
long SpringReference::steps() const {
  long n = 0;
  check(CVodeGetNumSteps(impl_->cvode, &n), "CVodeGetNumSteps");
  return n;
}

}  // namespace rig::paper
