// GDAL helpers shared by the stages that read rasters (mosaic, terrain). Internal: include from core
// .cpp files only.
#pragma once

#include <cpl_error.h>
#include <gdal_priv.h>

#include <string>

namespace pf::geo::detail {

// Registers GDAL's drivers once per process (thread-safe).
void ensureGdalRegistered();

// Collects GDAL's errors and warnings raised on this thread while alive, instead of printing them.
// GDAL keeps its handler stack per thread, so worker threads each need their own scope.
class GdalErrorCapture {
public:
    GdalErrorCapture();
    ~GdalErrorCapture();
    GdalErrorCapture(const GdalErrorCapture&) = delete;
    GdalErrorCapture& operator=(const GdalErrorCapture&) = delete;

    bool failed() const { return m_failures > 0; }
    bool warned() const { return m_warnings > 0; }
    // The first failure, else the first warning (GDAL's words), empty if none.
    std::string message() const { return m_firstFailure.empty() ? m_firstWarning : m_firstFailure; }

private:
    static void CPL_STDCALL handler(CPLErr level, CPLErrorNum no, const char* msg);
    int m_failures = 0;
    int m_warnings = 0;
    std::string m_firstFailure;
    std::string m_firstWarning;
};

// Opens a raster read-only, quietly; null if GDAL cannot read it.
GDALDatasetUniquePtr openRaster(const std::string& path,
                                const char* const* allowedDrivers = nullptr);

// "/a/b/IMG_0001.JPG" -> "IMG_0001.JPG", for messages.
std::string fileName(const std::string& path);

} // namespace pf::geo::detail
