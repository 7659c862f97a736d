#include "core/mosaic/camera_model.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace pf::mosaic {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
bool swapsAxes(int orientation) {
    return orientation >= 5 && orientation <= 8;
}
} // namespace

CameraModel::CameraModel(const CameraIntrinsics& in, const CameraPose& pose)
    : m_pose(pose), m_storedW(in.widthPx), m_storedH(in.heightPx), m_orientation(in.orientation) {
    if (m_orientation < 1 || m_orientation > 8)
        m_orientation = 1;
    const double wd = swapsAxes(m_orientation) ? m_storedH : m_storedW;
    const double hd = swapsAxes(m_orientation) ? m_storedW : m_storedH;
    const bool landscape = wd >= hd;
    const double fovX = (landscape ? in.longSideFovDeg : in.shortSideFovDeg) * kDeg;
    const double fovY = (landscape ? in.shortSideFovDeg : in.longSideFovDeg) * kDeg;
    m_cx = wd / 2.0;
    m_cy = hd / 2.0;
    m_fx = m_cx / std::tan(fovX / 2.0);
    m_fy = m_cy / std::tan(fovY / 2.0);

    // Camera axes (x right, y down, z along the view) for a camera looking north at the horizon,
    // then the gimbal: pitch about the right axis, roll about the forward axis, yaw about the
    // vertical.
    Eigen::Matrix3d base;
    base.col(0) = Vec3(1, 0, 0);
    base.col(1) = Vec3(0, 0, -1);
    base.col(2) = Vec3(0, 1, 0);
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(-pose.yawDeg * kDeg, Vec3::UnitZ()) *
                               Eigen::AngleAxisd(pose.rollDeg * kDeg, Vec3::UnitY()) *
                               Eigen::AngleAxisd(pose.pitchDeg * kDeg, Vec3::UnitX()))
                                  .toRotationMatrix();
    m_worldFromCamera = r * base;
}

void CameraModel::displayToStored(double x, double y, double* xs, double* ys) const {
    const double w = m_storedW, h = m_storedH;
    switch (m_orientation) {
    case 2:
        *xs = w - x;
        *ys = y;
        break;
    case 3:
        *xs = w - x;
        *ys = h - y;
        break;
    case 4:
        *xs = x;
        *ys = h - y;
        break;
    case 5:
        *xs = y;
        *ys = x;
        break;
    case 6:
        *xs = y;
        *ys = h - x;
        break;
    case 7:
        *xs = w - y;
        *ys = h - x;
        break;
    case 8:
        *xs = w - y;
        *ys = x;
        break;
    default:
        *xs = x;
        *ys = y;
        break;
    }
}

void CameraModel::storedToDisplay(double xs, double ys, double* x, double* y) const {
    const double w = m_storedW, h = m_storedH;
    switch (m_orientation) {
    case 2:
        *x = w - xs;
        *y = ys;
        break;
    case 3:
        *x = w - xs;
        *y = h - ys;
        break;
    case 4:
        *x = xs;
        *y = h - ys;
        break;
    case 5:
        *x = ys;
        *y = xs;
        break;
    case 6:
        *x = h - ys;
        *y = xs;
        break;
    case 7:
        *x = h - ys;
        *y = w - xs;
        break;
    case 8:
        *x = ys;
        *y = w - xs;
        break;
    default:
        *x = xs;
        *y = ys;
        break;
    }
}

bool CameraModel::project(const Vec3& ground, double* col, double* row) const {
    const Vec3 c = m_worldFromCamera.transpose() * (ground - m_pose.position);
    if (c.z() <= 1e-9)
        return false;
    displayToStored(m_cx + m_fx * c.x() / c.z(), m_cy + m_fy * c.y() / c.z(), col, row);
    return true;
}

Vec3 CameraModel::ray(double col, double row) const {
    double x = 0, y = 0;
    storedToDisplay(col, row, &x, &y);
    const Vec3 c((x - m_cx) / m_fx, (y - m_cy) / m_fy, 1.0);
    return (m_worldFromCamera * c).normalized();
}

double CameraModel::offNadirDeg() const {
    const Vec3 axis = m_worldFromCamera.col(2);
    return std::acos(std::clamp(-axis.z(), -1.0, 1.0)) / kDeg;
}

} // namespace pf::mosaic
