<?xml version="1.0" encoding="UTF-8"?>
<!-- As a commercial exporter writes it: no default namespace is declared, so the root CityModel and
     its cityObjectMember children are unqualified; the buildings are prefixed (bldg:, CityGML 2.0). -->
<CityModel xmlns:gml="http://www.opengis.net/gml" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
 xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
 <gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832" srsDimension="3">
  <gml:lowerCorner>500000 5400000 100</gml:lowerCorner><gml:upperCorner>500003 5400001 101</gml:upperCorner>
 </gml:Envelope></gml:boundedBy>
 <cityObjectMember>
  <bldg:Building gml:id="U1">
    <bldg:measuredHeight uom="m">1.0</bldg:measuredHeight>
    <bldg:lod1Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500000 5400000 100 500000 5400001 100 500001 5400001 100 500001 5400000 100 500000 5400000 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500000 5400000 101 500001 5400000 101 500001 5400001 101 500000 5400001 101 500000 5400000 101</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500000 5400000 100 500001 5400000 100 500001 5400000 101 500000 5400000 101 500000 5400000 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500001 5400000 100 500001 5400001 100 500001 5400001 101 500001 5400000 101 500001 5400000 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500001 5400001 100 500000 5400001 100 500000 5400001 101 500001 5400001 101 500001 5400001 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500000 5400001 100 500000 5400000 100 500000 5400000 101 500000 5400001 101 500000 5400001 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid>
  </bldg:Building>
 </cityObjectMember>
 <cityObjectMember>
  <bldg:Building gml:id="U2">
    <bldg:lod1Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500002 5400000 100 500002 5400001 100 500003 5400001 100 500003 5400000 100 500002 5400000 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500002 5400000 101 500003 5400000 101 500003 5400001 101 500002 5400001 101 500002 5400000 101</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500002 5400000 100 500003 5400000 100 500003 5400000 101 500002 5400000 101 500002 5400000 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500003 5400000 100 500003 5400001 100 500003 5400001 101 500003 5400000 101 500003 5400000 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500003 5400001 100 500002 5400001 100 500002 5400001 101 500003 5400001 101 500003 5400001 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>500002 5400001 100 500002 5400000 100 500002 5400000 101 500002 5400001 101 500002 5400001 100</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid>
  </bldg:Building>
 </cityObjectMember>
</CityModel>
