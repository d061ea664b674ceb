<?xml version="1.0" encoding="UTF-8"?>
<!-- GML surfaces besides gml:Polygon: a gml:Surface of two PolygonPatches, an OrientableSurface
     orientation="-" around a Polygon, and one around a Surface patch reached by xlink:href. -->
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
 xmlns:gml="http://www.opengis.net/gml" xmlns:xlink="http://www.w3.org/1999/xlink">
 <core:cityObjectMember>
  <bldg:Building gml:id="P" srsName="EPSG:28992">
    <bldg:lod1MultiSurface><gml:MultiSurface>
      <gml:surfaceMember><gml:OrientableSurface gml:id="OS" orientation="-"><gml:baseSurface><gml:Surface><gml:patches>
        <gml:PolygonPatch><gml:exterior><gml:LinearRing><gml:posList>0 0 7 1 0 7 1 1 7 0 0 7</gml:posList></gml:LinearRing></gml:exterior></gml:PolygonPatch>
      </gml:patches></gml:Surface></gml:baseSurface></gml:OrientableSurface></gml:surfaceMember>
    </gml:MultiSurface></bldg:lod1MultiSurface>
    <bldg:lod2MultiSurface><gml:MultiSurface>
      <gml:surfaceMember><gml:Surface gml:id="S1"><gml:patches>
        <gml:PolygonPatch><gml:exterior><gml:LinearRing><gml:posList>0 0 0 1 0 0 1 1 0 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:PolygonPatch>
        <gml:PolygonPatch><gml:exterior><gml:LinearRing><gml:posList>0 0 0 1 1 0 0 1 0 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:PolygonPatch>
      </gml:patches></gml:Surface></gml:surfaceMember>
      <gml:surfaceMember><gml:OrientableSurface orientation="-"><gml:baseSurface>
        <gml:Polygon gml:id="R"><gml:exterior><gml:LinearRing><gml:posList>0 0 5 1 0 5 1 1 5 0 1 5 0 0 5</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>
      </gml:baseSurface></gml:OrientableSurface></gml:surfaceMember>
      <gml:surfaceMember xlink:href="#OS"/>
    </gml:MultiSurface></bldg:lod2MultiSurface>
  </bldg:Building>
 </core:cityObjectMember>
</core:CityModel>
