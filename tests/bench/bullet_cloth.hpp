#pragma once
// Bullet's soft-body cloth on the cloth benchmarks' sheet (bench_cloth-explicit,
// bench_cloth-implicit): the peer a game programmer would use. The sheet is built the way
// Bullet's demos build cloth: CreatePatch with both diagonals (its links are our structural and
// shear springs; it has no bend links), the total mass spread evenly over the nodes, the two
// corners of the j = 0 edge pinned by a zero mass, one stepSimulation of h per step. Bullet is
// position-based: each link is pulled back towards its rest length `piterations` times a step
// (Bullet's default: once), so there is no stiffness K and no stability limit on h.
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <kit/cloth/cloth.hpp>

namespace kit_bench {

class BulletCloth {
 public:
  /// An n×n sheet of 1 m, horizontal at height 1 m, node (i, j) = j·n + i at
  /// (−0.5 + i/(n−1), 1, −0.5 + j/(n−1)) as on the kit's grid; `mass` [kg] in all, `gravity`
  /// [m/s²]; `iterations` position iterations a step (0: Bullet's default).
  BulletCloth(int n, double mass, const kit::Vec3& gravity, int iterations) : n_(n) {
    const btVector3 g(btScalar(gravity.x()), btScalar(gravity.y()), btScalar(gravity.z()));
    world_.setGravity(g);
    btSoftBodyWorldInfo& info = world_.getWorldInfo();
    info.m_gravity = g;
    info.m_sparsesdf.Initialize();
    cloth_ = btSoftBodyHelpers::CreatePatch(info, btVector3(-0.5, 1, -0.5), btVector3(0.5, 1, -0.5),
                                            btVector3(-0.5, 1, 0.5), btVector3(0.5, 1, 0.5), n, n, 0, true);
    cloth_->setTotalMass(btScalar(mass));
    cloth_->setMass(0, 0);
    cloth_->setMass(n - 1, 0);
    if (iterations > 0) cloth_->m_cfg.piterations = iterations;
    world_.addSoftBody(cloth_);
  }
  ~BulletCloth() {
    world_.removeSoftBody(cloth_);
    delete cloth_;
  }
  BulletCloth(const BulletCloth&) = delete;
  BulletCloth& operator=(const BulletCloth&) = delete;

  /// One step of h [s].
  void step(double h) { world_.stepSimulation(btScalar(h), 0); }

  /// The nodes' positions [m] and velocities [m/s], row j·n + i = node (i, j), as on the kit's grid.
  kit::NodeArray positions() const { return gather(&btSoftBody::Node::m_x); }
  kit::NodeArray velocities() const { return gather(&btSoftBody::Node::m_v); }

  /// The largest (l − L0)/L0 over the structural links (`structural`) and over all links, both
  /// structural and shear (`links`); NaN once a link is not finite.
  void max_strain(double& structural, double& links) const {
    structural = links = 0;
    for (int l = 0; l < cloth_->m_links.size(); ++l) {
      const btSoftBody::Link& link = cloth_->m_links[l];
      const double length = double((link.m_n[0]->m_x - link.m_n[1]->m_x).length());
      const double strain = length / double(link.m_rl) - 1;
      // Nodes sit in one array, node (i, j) at j·n + i: structural links join nodes 1 or n apart.
      const long jump = std::abs(link.m_n[0] - link.m_n[1]);
      if (!std::isfinite(strain)) {
        structural = links = NAN;
        return;
      }
      links = std::max(links, strain);
      if (jump == 1 || jump == n_) structural = std::max(structural, strain);
    }
  }

 private:
  kit::NodeArray gather(btVector3 btSoftBody::Node::*field) const {
    kit::NodeArray out(cloth_->m_nodes.size(), 3);
    for (int k = 0; k < cloth_->m_nodes.size(); ++k) {
      const btVector3& w = cloth_->m_nodes[k].*field;
      out.row(k) << double(w.x()), double(w.y()), double(w.z());
    }
    return out;
  }

  int n_;
  btSoftBodyRigidBodyCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btSoftRigidDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  btSoftBody* cloth_ = nullptr;
};

}  // namespace kit_bench
