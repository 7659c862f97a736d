<?xml version="1.0" encoding="utf-8" ?>
<ogr:FeatureCollection
     xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:schemaLocation="http://ogr.maptools.org/ area.xsd"
     xmlns:ogr="http://ogr.maptools.org/"
     xmlns:gml="http://www.opengis.net/gml">
  <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::4326"><gml:lowerCorner>49.0108309 8.3272608</gml:lowerCorner><gml:upperCorner>49.0133489 8.3327392</gml:upperCorner></gml:Envelope></gml:boundedBy>
                                                                                                                                            
  <ogr:featureMember>
    <ogr:area gml:id="area.0">
      <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::4326"><gml:lowerCorner>49.0108309 8.3272608</gml:lowerCorner><gml:upperCorner>49.0133489 8.3327392</gml:upperCorner></gml:Envelope></gml:boundedBy>
      <ogr:geometryProperty><gml:Polygon srsName="urn:ogc:def:crs:EPSG::4326"><gml:exterior><gml:LinearRing><gml:posList>49.0109209 8.3272608 49.0108309 8.3324653 49.0123597 8.3327392 49.0125396 8.3308218 49.0133489 8.3305478 49.013259 8.3273978 49.0109209 8.3272608</gml:posList></gml:LinearRing></gml:exterior><gml:interior><gml:LinearRing><gml:posList>49.0118201 8.3291782 49.0121799 8.3291782 49.0121799 8.3297261 49.0118201 8.3297261 49.0118201 8.3291782</gml:posList></gml:LinearRing></gml:interior></gml:Polygon></ogr:geometryProperty>
      <ogr:name>Rheinhafen</ogr:name>
    </ogr:area>
  </ogr:featureMember>
  <ogr:featureMember>
    <ogr:area gml:id="area.1">
      <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::4326"><gml:lowerCorner>49.0118201 8.3291782</gml:lowerCorner><gml:upperCorner>49.0121799 8.3297261</gml:upperCorner></gml:Envelope></gml:boundedBy>
      <ogr:geometryProperty><gml:Polygon srsName="urn:ogc:def:crs:EPSG::4326"><gml:exterior><gml:LinearRing><gml:posList>49.0118201 8.3291782 49.0118201 8.3297261 49.0121799 8.3297261 49.0121799 8.3291782 49.0118201 8.3291782</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></ogr:geometryProperty>
      <ogr:name>Warehouse</ogr:name>
    </ogr:area>
  </ogr:featureMember>
</ogr:FeatureCollection>
