<?xml version="1.0" encoding="UTF-8"?>
<!-- Four unit cubes in a row whose shared walls are defined once: B's west wall is A's east wall
     reversed, through an OrientableSurface that lies in a non-building object after A (and refers
     back into A); C's east wall is a polygon of D, later in the file, that D uses reversed. -->
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
 xmlns:gen="http://www.opengis.net/citygml/generics/2.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:xlink="http://www.w3.org/1999/xlink">
 <gml:boundedBy><gml:Envelope srsName="EPSG:28992" srsDimension="3">
  <gml:lowerCorner>0 0 0</gml:lowerCorner><gml:upperCorner>4 1 1</gml:upperCorner></gml:Envelope></gml:boundedBy>
 <core:cityObjectMember>
  <bldg:Building gml:id="A">
    <bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 0 0 1 0 1 1 0 1 0 0 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 1 1 0 1 1 1 1 0 1 1 0 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 0 1 0 0 1 0 1 0 0 1 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon gml:id="A-east"><gml:exterior><gml:LinearRing><gml:posList>1 0 0 1 1 0 1 1 1 1 0 1 1 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 1 0 0 1 0 0 1 1 1 1 1 1 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 1 0 0 0 0 0 0 1 0 1 1 0 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
  </bldg:Building>
 </core:cityObjectMember>
 <core:cityObjectMember>
  <gen:GenericCityObject gml:id="shared-walls"><gen:lod2Geometry><gml:MultiSurface>
    <gml:surfaceMember><gml:OrientableSurface gml:id="A-east-reversed" orientation="-"><gml:baseSurface xlink:href="#A-east"/></gml:OrientableSurface></gml:surfaceMember>
  </gml:MultiSurface></gen:lod2Geometry></gen:GenericCityObject>
 </core:cityObjectMember>
 <core:cityObjectMember>
  <bldg:Building gml:id="B">
    <bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 0 0 1 1 0 2 1 0 2 0 0 1 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 0 1 2 0 1 2 1 1 1 1 1 1 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 0 0 2 0 0 2 0 1 1 0 1 1 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 0 0 2 1 0 2 1 1 2 0 1 2 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 1 0 1 1 0 1 1 1 2 1 1 2 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember xlink:href="#A-east-reversed"/>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
  </bldg:Building>
 </core:cityObjectMember>
 <core:cityObjectMember>
  <bldg:Building gml:id="C">
    <bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 0 0 2 1 0 3 1 0 3 0 0 2 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 0 1 3 0 1 3 1 1 2 1 1 2 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 0 0 3 0 0 3 0 1 2 0 1 2 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember xlink:href="#CD"/>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>3 1 0 2 1 0 2 1 1 3 1 1 3 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 1 0 2 0 0 2 0 1 2 1 1 2 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
  </bldg:Building>
 </core:cityObjectMember>
 <core:cityObjectMember>
  <bldg:Building gml:id="D">
    <bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>3 0 0 3 1 0 4 1 0 4 0 0 3 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>3 0 1 4 0 1 4 1 1 3 1 1 3 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>3 0 0 4 0 0 4 0 1 3 0 1 3 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>4 0 0 4 1 0 4 1 1 4 0 1 4 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>4 1 0 3 1 0 3 1 1 4 1 1 4 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:OrientableSurface orientation="-"><gml:baseSurface><gml:Polygon gml:id="CD"><gml:exterior><gml:LinearRing><gml:posList>3 0 0 3 1 0 3 1 1 3 0 1 3 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:baseSurface></gml:OrientableSurface></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
  </bldg:Building>
 </core:cityObjectMember>
</core:CityModel>
