#!/bin/sh
# Regenerates the corridor fixtures in this folder from the centre line written below (a fictional
# stretch of river bank near Karlsruhe, Germany, 2.3 km with four bends) with GDAL's ogr2ogr. Run from
# anywhere: sh tests/data/corridor/make_fixtures.sh. The outputs are committed; run this only to change
# them. Needs gdal-bin.
set -eu
cd "$(dirname "$0")"
rm -f river.* river_25832.* two_lines.* no_line.*

cat > river.geojson <<'JSON'
{
"type": "FeatureCollection",
"features": [
{ "type": "Feature", "properties": { "name": "Alb bank" }, "geometry": { "type": "LineString", "coordinates": [
  [8.3200, 49.0100], [8.3290, 49.0112], [8.3352, 49.0150], [8.3420, 49.0158], [8.3470, 49.0131], [8.3530, 49.0140] ] } }
]
}
JSON
ogr2ogr -f KML river.kml river.geojson
ogr2ogr -f GPX -nlt MULTILINESTRING -lco FORCE_GPX_TRACK=YES river.gpx river.geojson
ogr2ogr -f "ESRI Shapefile" -t_srs EPSG:25832 river_25832.shp river.geojson
ogr2ogr -f GPKG river.gpkg river.geojson

# Two lines: a corridor follows one, so this file is refused with both names.
cat > two_lines.geojson <<'JSON'
{
"type": "FeatureCollection",
"features": [
{ "type": "Feature", "properties": { "name": "North bank" }, "geometry": { "type": "LineString", "coordinates": [
  [8.3200, 49.0110], [8.3300, 49.0120] ] } },
{ "type": "Feature", "properties": { "name": "South bank" }, "geometry": { "type": "LineString", "coordinates": [
  [8.3200, 49.0100], [8.3300, 49.0105] ] } }
]
}
JSON

# A polygon only: no line to follow.
cat > no_line.geojson <<'JSON'
{
"type": "FeatureCollection",
"features": [
{ "type": "Feature", "properties": { "name": "Field" }, "geometry": { "type": "Polygon", "coordinates": [
  [ [8.3200, 49.0100], [8.3300, 49.0100], [8.3300, 49.0150], [8.3200, 49.0100] ] ] } }
]
}
JSON
