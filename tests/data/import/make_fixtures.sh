#!/bin/sh
# Regenerates the importer fixtures in this folder from the coordinates written below (the demo site
# near Karlsruhe, Germany) with GDAL's ogr2ogr. Run from anywhere: sh tests/data/import/make_fixtures.sh
# The outputs are committed; run this only to change them. Needs gdal-bin.
set -eu
cd "$(dirname "$0")"
rm -f area.* area_* multi.* noprj_* points.* empty.* corrupt.* unsupported.*

# Source 1: the demo area with the "Warehouse" as a hole, plus the warehouse itself, WGS84.
cat > area.geojson <<'JSON'
{
"type": "FeatureCollection",
"features": [
{ "type": "Feature", "properties": { "name": "Rheinhafen" }, "geometry": { "type": "Polygon", "coordinates": [
  [ [8.3272608, 49.0109209], [8.3324653, 49.0108309], [8.3327392, 49.0123597], [8.3308218, 49.0125396],
    [8.3305478, 49.0133489], [8.3273978, 49.013259], [8.3272608, 49.0109209] ],
  [ [8.3291782, 49.0118201], [8.3291782, 49.0121799], [8.3297261, 49.0121799], [8.3297261, 49.0118201],
    [8.3291782, 49.0118201] ] ] } },
{ "type": "Feature", "properties": { "name": "Warehouse" }, "geometry": { "type": "Polygon", "coordinates": [
  [ [8.3291782, 49.0118201], [8.3297261, 49.0118201], [8.3297261, 49.0121799], [8.3291782, 49.0121799],
    [8.3291782, 49.0118201] ] ] } }
]
}
JSON

# Source 2: one feature made of two parcels (a MultiPolygon) and a feature without a name.
cat > multi.geojson <<'JSON'
{
"type": "FeatureCollection",
"features": [
{ "type": "Feature", "properties": { "name": "Two parcels" }, "geometry": { "type": "MultiPolygon", "coordinates": [
  [ [ [8.3280, 49.0140], [8.3290, 49.0140], [8.3290, 49.0146], [8.3280, 49.0146], [8.3280, 49.0140] ] ],
  [ [ [8.3300, 49.0140], [8.3312, 49.0140], [8.3312, 49.0147], [8.3300, 49.0140] ] ] ] } },
{ "type": "Feature", "properties": { }, "geometry": { "type": "Polygon", "coordinates": [
  [ [8.3320, 49.0140], [8.3325, 49.0140], [8.3325, 49.0144], [8.3320, 49.0140] ] ] } }
]
}
JSON

# Source 3: the demo area with heights (3D), to check that the importer flattens.
cat > area_3d.geojson <<'JSON'
{
"type": "FeatureCollection",
"features": [
{ "type": "Feature", "properties": { "name": "Rheinhafen 3D" }, "geometry": { "type": "Polygon", "coordinates": [
  [ [8.3272608, 49.0109209, 101.5], [8.3324653, 49.0108309, 102.0], [8.3327392, 49.0123597, 103.25],
    [8.3308218, 49.0125396, 99.0], [8.3305478, 49.0133489, 98.5], [8.3273978, 49.013259, 100.0],
    [8.3272608, 49.0109209, 101.5] ] ] } }
]
}
JSON

# Each supported format, some in projected systems.
ogr2ogr -f KML area.kml area.geojson
ogr2ogr -f "ESRI Shapefile" -t_srs EPSG:25832 area_25832.shp area.geojson
ogr2ogr -f GPKG -t_srs EPSG:3857 -nln area area_3857.gpkg area.geojson
ogr2ogr -f GML -dsco FORMAT=GML3 area.gml area.geojson
ogr2ogr -f GML -dsco FORMAT=GML3 -t_srs EPSG:25832 area_25832.gml area.geojson
ogr2ogr -f GPKG -dim XYZ -nln area_3d area_3d.gpkg area_3d.geojson
ogr2ogr -f KML multi.kml multi.geojson
ogr2ogr -f "ESRI Shapefile" -nlt MULTIPOLYGON multi.shp multi.geojson

# Shapefiles without their .prj: projected coordinates (must be refused) and lon/lat (accepted).
ogr2ogr -f "ESRI Shapefile" -t_srs EPSG:25832 noprj_25832.shp area.geojson
rm noprj_25832.prj
ogr2ogr -f "ESRI Shapefile" noprj_lonlat.shp area.geojson
rm noprj_lonlat.prj

# Files with nothing to import.
cat > points.geojson <<'JSON'
{ "type": "FeatureCollection", "features": [
  { "type": "Feature", "properties": { "name": "Home" }, "geometry": { "type": "Point", "coordinates": [8.3270554, 49.010741] } },
  { "type": "Feature", "properties": { "name": "Fence" }, "geometry": { "type": "LineString", "coordinates": [[8.327, 49.011], [8.328, 49.012]] } } ] }
JSON
printf '{ "type": "FeatureCollection", "features": [] }\n' > empty.geojson

# Damaged files: cut in the middle, or not what their extension says.
head -c 300 area.geojson > corrupt.geojson
head -c 400 area.kml > corrupt.kml
head -c 500 area.gml > corrupt.gml
printf 'This is not a GeoPackage but a text file with the wrong extension.\n' > corrupt.gpkg
head -c 60 area_25832.shp > corrupt.shp
cp area_25832.shx corrupt.shx
cp area_25832.dbf corrupt.dbf

# A format the importer does not offer (GDAL reads CSV, Photoflight refuses it) and an unknown one.
printf 'name,lon,lat\nHome,8.3270554,49.010741\n' > unsupported.csv
printf 'area: somewhere near the harbour\n' > unsupported.txt

rm -f *.gfs
