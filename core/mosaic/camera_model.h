// CameraModel: a pinhole camera at a pose (position and gimbal angles) mapping ground points to
// photo pixels and pixels to viewing rays, in a metric grid frame (x east, y north, z up).
#pragma once

#include <Eigen/Core>

namespace pf::mosaic {

using Vec3 = Eigen::Vector3d;

// Where the camera was and where it looked. Angles follow the gimbal convention of DJI's XMP (and
// of most drone cameras): yaw clockwise from grid north is where the top of the image points, pitch
// -90 looks straight down (0 at the horizon), roll turns the camera about the aircraft's forward
// axis (positive: its right side goes down, as a right bank, so a camera looking down sees to the
// left).
struct CameraPose {
    Vec3 position{0, 0, 0}; // grid metres; z in the vertical datum of the ground model
    double yawDeg = 0.0;
    double pitchDeg = -90.0;
    double rollDeg = 0.0;
};

// The photo as stored: its pixel size, the fields of view across its long and short sides, and the
// EXIF orientation (1..8) saying how the stored pixels are turned relative to the camera's view.
struct CameraIntrinsics {
    int widthPx = 0;  // stored
    int heightPx = 0; // stored
    double longSideFovDeg = 0.0;
    double shortSideFovDeg = 0.0;
    int orientation = 1;
};

class CameraModel {
public:
    CameraModel() = default;
    CameraModel(const CameraIntrinsics& intrinsics, const CameraPose& pose);

    // Stored-pixel coordinates (GDAL convention: (0, 0) is the top-left corner of the first pixel)
    // of a ground point; false if the point is behind the camera.
    bool project(const Vec3& ground, double* col, double* row) const;
    // True if the stored-pixel coordinates lie inside the photo, `marginPx` from its edges.
    bool inside(double col, double row, double marginPx = 0.0) const {
        return col >= marginPx && row >= marginPx && col <= m_storedW - marginPx &&
               row <= m_storedH - marginPx;
    }
    // Unit viewing direction through a stored pixel position, in the grid frame.
    Vec3 ray(double col, double row) const;

    const Vec3& centre() const { return m_pose.position; }
    const CameraPose& pose() const { return m_pose; }
    int storedWidth() const { return m_storedW; }
    int storedHeight() const { return m_storedH; }
    // Ground metres per pixel at the image centre for a flat ground `heightAboveGroundM` below,
    // looking straight down.
    double nadirGsdM(double heightAboveGroundM) const { return heightAboveGroundM / m_fx; }
    // Angle between the optical axis and the vertical, degrees (0: nadir).
    double offNadirDeg() const;

private:
    void displayToStored(double xd, double yd, double* xs, double* ys) const;
    void storedToDisplay(double xs, double ys, double* xd, double* yd) const;

    CameraPose m_pose;
    Eigen::Matrix3d m_worldFromCamera = Eigen::Matrix3d::Identity(); // columns: camera x, y, z axes
    double m_fx = 1.0, m_fy = 1.0, m_cx = 0.0, m_cy = 0.0;           // display pixels
    int m_storedW = 0, m_storedH = 0;
    int m_orientation = 1;
};

} // namespace pf::mosaic
