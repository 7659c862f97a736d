#include "core/geo/gdal_util.h"

#include <filesystem>
#include <mutex>

namespace pf::geo::detail {

void ensureGdalRegistered() {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
}

GdalErrorCapture::GdalErrorCapture() {
    CPLPushErrorHandlerEx(&GdalErrorCapture::handler, this);
}

GdalErrorCapture::~GdalErrorCapture() {
    CPLPopErrorHandler();
}

void CPL_STDCALL GdalErrorCapture::handler(CPLErr level, CPLErrorNum, const char* msg) {
    auto* self = static_cast<GdalErrorCapture*>(CPLGetErrorHandlerUserData());
    if (!self)
        return;
    if (level >= CE_Failure) {
        if (self->m_failures++ == 0)
            self->m_firstFailure = msg ? msg : "";
    } else if (level == CE_Warning) {
        if (self->m_warnings++ == 0)
            self->m_firstWarning = msg ? msg : "";
    }
}

GDALDatasetUniquePtr openRaster(const std::string& path, const char* const* allowedDrivers) {
    ensureGdalRegistered();
    return GDALDatasetUniquePtr(
        GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, allowedDrivers));
}

std::string fileName(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    return name.empty() ? path : name;
}

} // namespace pf::geo::detail
