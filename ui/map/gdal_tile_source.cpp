#include "ui/map/gdal_tile_source.h"

#include "ui/map/web_mercator.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

#include <QAtomicInt>
#include <QDir>

namespace pf::ui {

namespace {

// Silences GDAL's stderr output for the current thread while it lives: failures reach the user
// as a missing tile or an error message, not as console noise.
struct QuietErrors {
    QuietErrors() { CPLPushErrorHandler(CPLQuietErrorHandler); }
    ~QuietErrors() { CPLPopErrorHandler(); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;
};

QString lastGdalError() {
    const QString msg = QString::fromUtf8(CPLGetLastErrorMsg()).trimmed();
    return msg.isEmpty() ? QObject::tr("unknown GDAL error") : msg;
}

const char* webMercatorWkt() {
    static const QByteArray wkt = [] {
        OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
        OSRImportFromEPSG(srs, 3857);
        char* text = nullptr;
        OSRExportToWkt(srs, &text);
        QByteArray out(text);
        CPLFree(text);
        OSRDestroySpatialReference(srs);
        return out;
    }();
    return wkt.constData();
}

QAtomicInt g_vsimemCounter;

} // namespace

std::unique_ptr<GdalTileSource> GdalTileSource::open(const QString& datasetName, const QString& displayName,
                                                     QString* error) {
    GDALAllRegister();
    QuietErrors quiet;
    auto fail = [&](const QString& why) {
        if (error) *error = QObject::tr("Cannot use %1 as a map: %2").arg(displayName, why);
        return nullptr;
    };
    QByteArray name = datasetName.toUtf8();
    GDALDatasetH ds = GDALOpenEx(name.constData(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    if (!ds) return fail(lastGdalError());
    const int bands = GDALGetRasterCount(ds);
    if (bands == 0) {
        GDALClose(ds);
        return fail(QObject::tr("it contains no raster image"));
    }
    if (!GDALGetSpatialRef(ds) && GDALGetGCPCount(ds) == 0) {
        GDALClose(ds);
        return fail(QObject::tr("it has no coordinate reference system, so it cannot be placed on the map"));
    }

    // Normalise what the warper cannot turn into RGBA directly (palettes, 16-bit or float data,
    // extra bands) through a VRT in GDAL's in-memory file system that every pooled handle reopens.
    GDALRasterBandH b1 = GDALGetRasterBand(ds, 1);
    const bool palette = GDALGetRasterColorTable(b1) != nullptr;
    const bool nonByte = GDALGetRasterDataType(b1) != GDT_Byte;
    const bool hasAlpha = GDALGetRasterColorInterpretation(GDALGetRasterBand(ds, bands)) == GCI_AlphaBand;
    const int colourBands = palette ? 3 : (bands - (hasAlpha ? 1 : 0) >= 3 ? 3 : 1);
    const bool extraBands = !palette && bands - (hasAlpha ? 1 : 0) != colourBands;
    QString vsimem;
    if (palette || nonByte || extraBands) {
        QStringList args{QStringLiteral("-of"), QStringLiteral("VRT")};
        if (palette) args << QStringLiteral("-expand") << QStringLiteral("rgba");
        if (nonByte) args << QStringLiteral("-ot") << QStringLiteral("Byte") << QStringLiteral("-scale");
        if (extraBands) {
            for (int b = 1; b <= colourBands; ++b) args << QStringLiteral("-b") << QString::number(b);
            if (hasAlpha) args << QStringLiteral("-b") << QString::number(bands);
        }
        std::vector<QByteArray> storage;
        std::vector<char*> argv;
        for (const auto& a : args) storage.push_back(a.toUtf8());
        for (auto& s : storage) argv.push_back(s.data());
        argv.push_back(nullptr);
        GDALTranslateOptions* opts = GDALTranslateOptionsNew(argv.data(), nullptr);
        vsimem = QStringLiteral("/vsimem/pf_map_%1.vrt").arg(g_vsimemCounter.fetchAndAddRelaxed(1));
        GDALDatasetH vrt = GDALTranslate(vsimem.toUtf8().constData(), ds, opts, nullptr);
        GDALTranslateOptionsFree(opts);
        GDALClose(ds);
        if (!vrt) return fail(lastGdalError());
        ds = vrt;
        name = vsimem.toUtf8();
    }

    // Where the data lies in Web Mercator, and how fine it is.
    const char* tOpts[] = {"DST_SRS=EPSG:3857", nullptr};
    void* transformer = GDALCreateGenImgProjTransformer2(ds, nullptr, const_cast<char**>(tOpts));
    double gt[6] = {};
    int w = 0, h = 0;
    const bool suggested = transformer && GDALSuggestedWarpOutput(ds, GDALGenImgProjTransform, transformer, gt, &w, &h) == CE_None;
    if (transformer) GDALDestroyGenImgProjTransformer(transformer);
    if (!suggested) {
        GDALClose(ds);
        if (!vsimem.isEmpty()) VSIUnlink(vsimem.toUtf8().constData());
        return fail(QObject::tr("it cannot be reprojected to Web Mercator (%1)").arg(lastGdalError()));
    }

    std::unique_ptr<GdalTileSource> src(new GdalTileSource());
    src->m_datasetName = name;
    src->m_displayName = displayName;
    src->m_vsimemPath = vsimem;
    src->m_colourBands = colourBands;
    src->m_coverage = QRectF(gt[0], -gt[3], w * gt[1], h * -gt[5]).intersected(
        QRectF(-mercator::kHalfWorld, -mercator::kHalfWorld, 2 * mercator::kHalfWorld, 2 * mercator::kHalfWorld));
    src->m_maxZoom = mercator::zoomForResolution(gt[1]);
    if (char** md = GDALGetMetadata(ds, nullptr)) {
        for (int i = 0; md[i]; ++i) {
            const QString item = QString::fromUtf8(md[i]);
            const int eq = item.indexOf(QLatin1Char('='));
            if (eq > 0) src->m_metadata.insert(item.left(eq), item.mid(eq + 1));
        }
    }
    src->m_all.push_back(ds);
    src->m_free.push_back(ds);
    return src;
}

QString GdalTileSource::xyzServiceXml(const QString& urlTemplate, const QString& cacheDir, int maxZoom,
                                      int timeoutSeconds) {
    QString url = urlTemplate.toHtmlEscaped();
    // GDAL's TMS service expects ${z}/${x}/${y}; accept the common {z}/{x}/{y} spelling too.
    for (const char* v : {"z", "x", "y"}) {
        const QString plain = QStringLiteral("{%1}").arg(QLatin1String(v));
        const QString dollar = QStringLiteral("${%1}").arg(QLatin1String(v));
        if (!url.contains(dollar)) url.replace(plain, dollar);
    }
    return QStringLiteral(
               "<GDAL_WMS>"
               "<Service name=\"TMS\"><ServerUrl>%1</ServerUrl></Service>"
               "<DataWindow><UpperLeftX>-20037508.34</UpperLeftX><UpperLeftY>20037508.34</UpperLeftY>"
               "<LowerRightX>20037508.34</LowerRightX><LowerRightY>-20037508.34</LowerRightY>"
               "<TileLevel>%2</TileLevel><TileCountX>1</TileCountX><TileCountY>1</TileCountY>"
               "<YOrigin>top</YOrigin></DataWindow>"
               "<Projection>EPSG:3857</Projection><BlockSizeX>256</BlockSizeX><BlockSizeY>256</BlockSizeY>"
               "<BandsCount>3</BandsCount><MaxConnections>2</MaxConnections><Timeout>%3</Timeout>"
               "<UserAgent>Photoflight/%4</UserAgent>"
               "<ZeroBlockHttpCodes>204,404</ZeroBlockHttpCodes><ZeroBlockOnServerException>true</ZeroBlockOnServerException>"
               "<Cache><Path>%5</Path></Cache>"
               "</GDAL_WMS>")
        .arg(url)
        .arg(maxZoom)
        .arg(timeoutSeconds)
        .arg(QStringLiteral(PF_VERSION), cacheDir.toHtmlEscaped());
}

std::unique_ptr<GdalTileSource> GdalTileSource::openXyz(const QString& displayName, const QString& urlTemplate,
                                                        const QString& cacheDir, const QString& attribution,
                                                        int maxZoom, int timeoutSeconds) {
    QDir().mkpath(cacheDir);
    QString error;
    // Opening the WMS description reads no tile, so this does not touch the network.
    auto src = open(xyzServiceXml(urlTemplate, cacheDir, maxZoom, timeoutSeconds), displayName, &error);
    if (!src) return nullptr;
    src->m_attribution = attribution;
    src->m_online = true;
    src->m_maxZoom = maxZoom;
    src->m_resampling = "near"; // tiles align with the service's own: no neighbour tile fetched for a kernel
    src->m_timeout = QByteArray::number(timeoutSeconds);
    return src;
}

GdalTileSource::~GdalTileSource() {
    for (void* ds : m_all) GDALClose(static_cast<GDALDatasetH>(ds));
    if (!m_vsimemPath.isEmpty()) VSIUnlink(m_vsimemPath.toUtf8().constData());
}

QString GdalTileSource::metadataItem(const QString& key) const { return m_metadata.value(key); }

void* GdalTileSource::acquire() {
    {
        QMutexLocker lock(&m_mutex);
        if (!m_free.empty()) {
            void* ds = m_free.back();
            m_free.pop_back();
            return ds;
        }
    }
    GDALDatasetH ds = GDALOpenEx(m_datasetName.constData(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    if (ds) {
        QMutexLocker lock(&m_mutex);
        m_all.push_back(ds);
    }
    return ds;
}

void GdalTileSource::release(void* ds) {
    QMutexLocker lock(&m_mutex);
    m_free.push_back(ds);
}

QImage GdalTileSource::renderTile(const TileKey& key) {
    const QRectF rect = mercator::tileRect(key.z, key.x, key.y);
    if (!rect.intersects(m_coverage)) return {};
    QuietErrors quiet;
    if (m_online) {
        // Fail fast when offline: a tile that does not come quickly is simply left out.
        CPLSetThreadLocalConfigOption("GDAL_HTTP_TIMEOUT", m_timeout.constData());
        CPLSetThreadLocalConfigOption("GDAL_HTTP_CONNECTTIMEOUT", "3");
        CPLSetThreadLocalConfigOption("GDAL_HTTP_MAX_RETRY", "0");
    }
    auto* src = static_cast<GDALDatasetH>(acquire());
    if (!src) return {};
    const int n = mercator::kTileSize;
    const int bandCount = m_colourBands + 1;
    GDALDatasetH mem = GDALCreate(GDALGetDriverByName("MEM"), "", n, n, bandCount, GDT_Byte, nullptr);
    double gt[6] = {rect.left(), rect.width() / n, 0.0, -rect.top(), 0.0, -rect.height() / n};
    GDALSetGeoTransform(mem, gt);
    GDALSetProjection(mem, webMercatorWkt());
    GDALSetRasterColorInterpretation(GDALGetRasterBand(mem, bandCount), GCI_AlphaBand);

    const char* args[] = {"-r", m_resampling.constData(), "-dstalpha", nullptr};
    GDALWarpAppOptions* opts = GDALWarpAppOptionsNew(const_cast<char**>(args), nullptr);
    GDALDatasetH sources[1] = {src};
    int usageError = 0;
    GDALDatasetH warped = GDALWarp(nullptr, mem, 1, sources, opts, &usageError);
    GDALWarpAppOptionsFree(opts);
    release(src);

    QImage img;
    if (warped) {
        img = QImage(n, n, QImage::Format_RGBA8888);
        int rgba[4] = {1, 2, 3, 4};
        int grey[4] = {1, 1, 1, 2};
        if (GDALDatasetRasterIO(mem, GF_Read, 0, 0, n, n, img.bits(), n, n, GDT_Byte, 4,
                                m_colourBands == 3 ? rgba : grey, 4, img.bytesPerLine(), 1) != CE_None)
            img = QImage();
    }
    GDALClose(mem);
    return img;
}

} // namespace pf::ui
