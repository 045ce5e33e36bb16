#pragma once
/// @file
/// The wheels' contacts of one force evaluation. The stepper asks the framework for dq/dy, dq/dz
/// and then for q at the same (y, z) (solver/mechanical_stepper.h, eq. 8), and both need every
/// wheel's contact. The partials open an evaluation at their (y, z) and keep each contact found;
/// the applied forces that follow take them if their (y, z) is the same bit for bit, and close
/// the evaluation: the workspace (spin axes, road planes) may change before the next one.

#include <array>
#include <cstring>

#include <Eigen/Core>

#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/wheel_contact.h"

namespace rig::model::vehicle {

class EvaluationContacts {
 public:
  using Vector = Eigen::VectorXd;

  explicit EvaluationContacts(Eigen::Index n) : y_(Vector::Zero(n)), z_(Vector::Zero(n)) {}

  /// Starts an evaluation at (y, z); `reuse`: keep what the open one holds if it is at (y, z).
  void open(const Vector& y, const Vector& z, bool reuse) noexcept {
    if (y.size() != y_.size() || z.size() != z_.size()) {  // not the framework's: keep nothing
      close();
      return;
    }
    if (reuse && open_ && same_bits(y, y_) && same_bits(z, z_)) return;
    known_.fill(false);
    y_ = y;  // the same size: no allocation
    z_ = z;
    open_ = true;
  }
  void close() noexcept {
    open_ = false;
    known_.fill(false);
  }

  /// Wheel i's contact: the one kept in this evaluation, else find() (kept if open).
  template <typename Find>
  [[nodiscard]] WheelContact get(int i, const Find& find) noexcept {
    const auto k = static_cast<std::size_t>(i);
    if (!open_) return find();
    if (!known_[k]) {
      contacts_[k] = find();
      known_[k] = true;
    }
    return contacts_[k];
  }

 private:
  static bool same_bits(const Vector& a, const Vector& b) noexcept {
    return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) ==
           0;
  }

  Vector y_, z_;
  bool open_ = false;
  std::array<bool, static_cast<std::size_t>(kMaxWheels)> known_{};
  std::array<WheelContact, static_cast<std::size_t>(kMaxWheels)> contacts_{};
};

}  // namespace rig::model::vehicle
