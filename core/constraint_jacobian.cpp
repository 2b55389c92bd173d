#include "core/constraint_jacobian.hpp"

#include <stdexcept>

namespace tribo {

void ConstraintJacobian::init(const std::vector<ConstraintRow>& rows, int body_count) {
  bodies_.clear();
  slot_of_body_.assign(body_count, -1);
  where_.assign(rows.size(), {});
  block_count_.assign(rows.size(), 0);
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    block_count_[r] = rows[r].body_count;
    for (int k = 0; k < rows[r].body_count; ++k) {
      const int b = rows[r].body[k];
      if (slot_of_body_[b] < 0) {
        slot_of_body_[b] = static_cast<int>(bodies_.size());
        bodies_.emplace_back();
        bodies_.back().body = b;
      }
      BodyRows& br = bodies_[slot_of_body_[b]];
      where_[r][k] = {slot_of_body_[b], static_cast<int>(br.rows.size())};
      br.rows.push_back(r);
    }
  }
  for (BodyRows& br : bodies_) {
    const int n = static_cast<int>(br.rows.size());
    br.j.setZero(n, 6);
    br.minv_j.setZero(n, 6);
  }
}

std::vector<std::pair<int, int>> ConstraintJacobian::pattern() const {
  std::vector<std::pair<int, int>> entries;
  for (int r = 0; r < static_cast<int>(where_.size()); ++r) entries.emplace_back(r, r);
  for (const BodyRows& br : bodies_)
    for (std::size_t i = 0; i < br.rows.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) entries.emplace_back(br.rows[i], br.rows[j]);
  return entries;
}

void ConstraintJacobian::bindSlots(const MultiplierMatrix& matrix) {
  for (BodyRows& br : bodies_) {
    const int n = static_cast<int>(br.rows.size());
    br.slots.assign(n * (n + 1) / 2, -1);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j <= i; ++j) {
        const int slot = matrix.slot(br.rows[i], br.rows[j]);
        if (slot < 0) throw std::logic_error("ConstraintJacobian: an entry outside the pattern");
        br.slots[i * (i + 1) / 2 + j] = slot;
      }
    }
  }
}

void ConstraintJacobian::setRow(int r, const RowValue& value) {
  for (int k = 0; k < block_count_[r]; ++k) {
    const Place& place = where_[r][k];
    bodies_[place.slot].j.row(place.local) = value.j[k];
  }
}

void ConstraintJacobian::computeMassWeighted(const std::vector<double>& inv_mass,
                                             const std::vector<Mat3>& inv_inertia_world) {
  for (BodyRows& br : bodies_) {
    br.minv_j.leftCols<3>() = br.j.leftCols<3>() * inv_mass[br.body];
    br.minv_j.rightCols<3>().noalias() = br.j.rightCols<3>() * inv_inertia_world[br.body];
  }
}

void ConstraintJacobian::assemble(MultiplierMatrix& matrix) const {
  double* values = matrix.values();
  for (const BodyRows& br : bodies_) {
    const int n = static_cast<int>(br.rows.size());
    const int* slot = br.slots.data();
    for (int i = 0; i < n; ++i) {
      const Row6 ji = br.j.row(i);
      for (int j = 0; j <= i; ++j) values[*slot++] += ji.dot(br.minv_j.row(j));
    }
  }
}

void ConstraintJacobian::addJx(const std::vector<Vec3>& linear, const std::vector<Vec3>& angular,
                               double sign, Eigen::VectorXd& out) const {
  for (const BodyRows& br : bodies_) {
    Row6 x;
    x << linear[br.body].transpose(), angular[br.body].transpose();
    for (std::size_t i = 0; i < br.rows.size(); ++i) out(br.rows[i]) += sign * br.j.row(i).dot(x);
  }
}

void ConstraintJacobian::addJMinvF(const std::vector<Wrench>& f, double sign,
                                   Eigen::VectorXd& out) const {
  for (const BodyRows& br : bodies_) {
    Row6 x;
    x << f[br.body].force.transpose(), f[br.body].torque.transpose();
    for (std::size_t i = 0; i < br.rows.size(); ++i)
      out(br.rows[i]) += sign * br.minv_j.row(i).dot(x);
  }
}

void ConstraintJacobian::applyMultipliers(const Eigen::VectorXd& lambda, std::vector<Vec3>& linear,
                                          std::vector<Vec3>& angular,
                                          std::vector<Wrench>* wrench) const {
  for (const BodyRows& br : bodies_) {
    Row6 acceleration = Row6::Zero(), force = Row6::Zero();
    for (std::size_t i = 0; i < br.rows.size(); ++i) {
      const double l = lambda(br.rows[i]);
      acceleration += l * br.minv_j.row(i);
      force += l * br.j.row(i);
    }
    linear[br.body] += acceleration.head<3>().transpose();
    angular[br.body] += acceleration.tail<3>().transpose();
    if (wrench) {
      (*wrench)[br.body].force += force.head<3>().transpose();
      (*wrench)[br.body].torque += force.tail<3>().transpose();
    }
  }
}

Row6 ConstraintJacobian::block(int r, int body) const {
  for (int k = 0; k < block_count_[r]; ++k) {
    const Place& place = where_[r][k];
    if (bodies_[place.slot].body == body) return bodies_[place.slot].j.row(place.local);
  }
  return Row6::Zero();
}

}  // namespace tribo
