<?xml version="1.0" encoding="utf-8" ?>
<ogr:FeatureCollection
     xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:schemaLocation="http://ogr.maptools.org/ area_25832.xsd"
     xmlns:ogr="http://ogr.maptools.org/"
     xmlns:gml="http://www.opengis.net/gml">
  <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832"><gml:lowerCorner>450805.071748274 5428874.45145425</gml:lowerCorner><gml:upperCorner>451207.090449542 5429155.5984687</gml:upperCorner></gml:Envelope></gml:boundedBy>
                                                                                                                  
  <ogr:featureMember>
    <ogr:area gml:id="area.0">
      <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832"><gml:lowerCorner>450805.071748274 5428874.45145425</gml:lowerCorner><gml:upperCorner>451207.090449542 5429155.5984687</gml:upperCorner></gml:Envelope></gml:boundedBy>
      <ogr:geometryProperty><gml:Polygon srsName="urn:ogc:def:crs:EPSG::25832"><gml:exterior><gml:LinearRing><gml:posList>450805.071748274 5428887.81643181 451185.567193116 5428874.45145425 451207.090449542 5429044.22352825 451067.059315605 5429065.45639146 451047.817003728 5429155.5984687 450817.393253678 5429147.64119588 450805.071748274 5428887.81643181</gml:posList></gml:LinearRing></gml:exterior><gml:interior><gml:LinearRing><gml:posList>450946.16667608 5428986.53451175 450946.520176865 5429026.53147444 450986.584813779 5429026.17751919 450986.23160174 5428986.18055588 450946.16667608 5428986.53451175</gml:posList></gml:LinearRing></gml:interior></gml:Polygon></ogr:geometryProperty>
      <ogr:name>Rheinhafen</ogr:name>
    </ogr:area>
  </ogr:featureMember>
  <ogr:featureMember>
    <ogr:area gml:id="area.1">
      <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832"><gml:lowerCorner>450946.16667608 5428986.18055588</gml:lowerCorner><gml:upperCorner>450986.584813779 5429026.53147444</gml:upperCorner></gml:Envelope></gml:boundedBy>
      <ogr:geometryProperty><gml:Polygon srsName="urn:ogc:def:crs:EPSG::25832"><gml:exterior><gml:LinearRing><gml:posList>450946.16667608 5428986.53451175 450986.23160174 5428986.18055588 450986.584813779 5429026.17751919 450946.520176865 5429026.53147444 450946.16667608 5428986.53451175</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></ogr:geometryProperty>
      <ogr:name>Warehouse</ogr:name>
    </ogr:area>
  </ogr:featureMember>
</ogr:FeatureCollection>
