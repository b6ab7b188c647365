// Local-PCA normals (Hoppe et al. 1992).
#include "src/fit/local_normals.h"

#include <Eigen/Eigenvalues>
#include <vector>

#include "src/fit/grid_index.h"
#include "src/fit/parallel.h"

namespace polarform {

Eigen::Matrix3Xd local_normals(const Eigen::Matrix3Xd& P, int k, int threads) {
  const GridIndex3d grid(P);
  Eigen::Matrix3Xd normals = Eigen::Matrix3Xd::Zero(3, P.cols());
  const int chunks = worker_count(threads, static_cast<std::size_t>(P.cols()));
  parallel_chunks(
      static_cast<std::size_t>(P.cols()), chunks, [&](std::size_t b, std::size_t e, int) {
        std::vector<int> near;
        for (std::size_t i = b; i < e; ++i) {
          const Eigen::Index c = static_cast<Eigen::Index>(i);
          grid.nearest(P.col(c), k, near);
          if (near.size() < 3) continue;
          Eigen::Vector3d m = Eigen::Vector3d::Zero();
          for (int j : near) m += P.col(j);
          m /= static_cast<double>(near.size());
          Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
          for (int j : near) C += (P.col(j) - m) * (P.col(j) - m).transpose();
          normals.col(c) = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvectors().col(0);
        }
      });
  return normals;
}

}  // namespace polarform
