<?xml version="1.0" encoding="UTF-8"?>
<!-- PLATEAU-style ADE content (i-UR uro: and urf: namespaces) beside CityGML 2.0 buildings: ADE
     properties of a Building, a BuildingPart and a boundary surface, and a top-level ADE city object. -->
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
 xmlns:gml="http://www.opengis.net/gml" xmlns:xlink="http://www.w3.org/1999/xlink"
 xmlns:uro="https://www.geospatial.jp/iur/uro/2.0" xmlns:urf="https://www.geospatial.jp/iur/urf/2.0">
 <gml:boundedBy><gml:Envelope srsName="http://www.opengis.net/def/crs/EPSG/0/6677" srsDimension="3">
  <gml:lowerCorner>0 0 0</gml:lowerCorner><gml:upperCorner>3 1 1</gml:upperCorner></gml:Envelope></gml:boundedBy>
 <core:cityObjectMember>
  <bldg:Building gml:id="bldg_1">
    <bldg:measuredHeight uom="m">1.0</bldg:measuredHeight>
    <bldg:lod1Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 0 0 1 0 1 1 0 1 0 0 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 1 1 0 1 1 1 1 0 1 1 0 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 0 0 1 0 0 1 0 1 0 0 1 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 0 0 1 1 0 1 1 1 1 0 1 1 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 1 0 0 1 0 0 1 1 1 1 1 1 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>0 1 0 0 0 0 0 0 1 0 1 1 0 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid>
    <uro:buildingDetailAttribute><uro:BuildingDetailAttribute><uro:surveyYear>2020</uro:surveyYear></uro:BuildingDetailAttribute></uro:buildingDetailAttribute>
    <uro:buildingIDAttribute><uro:BuildingIDAttribute><uro:buildingID>13101-bldg-1</uro:buildingID></uro:BuildingIDAttribute></uro:buildingIDAttribute>
  </bldg:Building>
 </core:cityObjectMember>
 <core:cityObjectMember>
  <bldg:Building gml:id="bldg_2">
    <uro:buildingDetailAttribute><uro:BuildingDetailAttribute><uro:surveyYear>2021</uro:surveyYear></uro:BuildingDetailAttribute></uro:buildingDetailAttribute>
    <bldg:consistsOfBuildingPart><bldg:BuildingPart gml:id="bldg_2_part">
    <bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 0 0 2 1 0 3 1 0 3 0 0 2 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon gml:id="roof-poly"><gml:exterior><gml:LinearRing><gml:posList>2 0 1 3 0 1 3 1 1 2 1 1 2 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 0 0 3 0 0 3 0 1 2 0 1 2 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>3 0 0 3 1 0 3 1 1 3 0 1 3 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>3 1 0 2 1 0 2 1 1 3 1 1 3 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
      <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>2 1 0 2 0 0 2 0 1 2 1 1 2 1 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
    </gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
    <uro:buildingDetailAttribute><uro:BuildingDetailAttribute><uro:surveyYear>2021</uro:surveyYear></uro:BuildingDetailAttribute></uro:buildingDetailAttribute>
    <bldg:boundedBy><bldg:RoofSurface gml:id="roof">
      <uro:buildingDisasterRiskAttribute><uro:BuildingRiverFloodingRiskAttribute><uro:rank>1</uro:rank></uro:BuildingRiverFloodingRiskAttribute></uro:buildingDisasterRiskAttribute>
      <bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember xlink:href="#roof-poly"/></gml:MultiSurface></bldg:lod2MultiSurface>
    </bldg:RoofSurface></bldg:boundedBy>
    </bldg:BuildingPart></bldg:consistsOfBuildingPart>
  </bldg:Building>
 </core:cityObjectMember>
 <core:cityObjectMember>
  <urf:UseDistrict gml:id="ud_1"><urf:function>1</urf:function></urf:UseDistrict>
 </core:cityObjectMember>
</core:CityModel>
