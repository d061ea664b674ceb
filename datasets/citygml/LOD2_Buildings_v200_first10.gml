<?xml version="1.0" encoding="ISO-8859-1" standalone="yes"?>
<CityModel xmlns="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml"
   xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
  xsi:schemaLocation="http://www.opengis.net/citygml/building/2.0 http://schemas.opengis.net/citygml/building/2.0/building.xsd">
  <gml:name>EasyCityGMLTestcase</gml:name>
  <gml:boundedBy>
    <gml:Envelope>
      <gml:pos srsDimension="3">0.0 0.0 0.0</gml:pos>
      <gml:pos srsDimension="3">100.0 100.0 10.0</gml:pos>
    </gml:Envelope>
  </gml:boundedBy>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_1F3E679D-E226-4535-926C-7390977FB25A">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-0_LoD2</gml:name>
      <bldg:class>1100</bldg:class>
      <bldg:yearOfConstruction>1929</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2044</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">11.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">2.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_7076142D-B7D1-48B6-901B-20CDB5968DF5">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">6.0 0.0 0.0 0.0 0.0 0.0 0.0 8.0 0.0 6.0 8.0 0.0 6.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_227D72FE-7D2C-4336-8D6C-24AFABF8A4DB">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">0.0 0.0 0.0 6.0 0.0 0.0 6.0 0.0 5.0 3.0 0.0 11.0 0.0 0.0 5.0 0.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_C8C2E28B-8FAC-4E56-AFA6-C403F47F4DA3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">6.0 8.0 0.0 0.0 8.0 0.0 0.0 8.0 5.0 3.0 8.0 11.0 6.0 8.0 5.0 6.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_8CC57495-6C1A-4F6F-9589-06CAAFC8EAF6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">0.0 0.0 0.0 0.0 0.0 5.0 0.0 8.0 5.0 0.0 8.0 0.0 0.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_9959A80E-FAC6-4F18-AA8C-27B4C853164C">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">6.0 8.0 0.0 6.0 8.0 5.0 6.0 0.0 5.0 6.0 0.0 0.0 6.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_8225CA5F-2613-40E5-BA61-117AFA2628B9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">0.0 0.0 5.0 3.0 0.0 11.0 3.0 8.0 11.0 0.0 8.0 5.0 0.0 0.0 5.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_9D7AB241-5B65-47B2-A4E3-802A63213A1F">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">6.0 8.0 5.0 3.0 8.0 11.0 3.0 0.0 11.0 6.0 0.0 5.0 6.0 8.0 5.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_7C605DB2-2E94-4C2D-82CC-8B9065F7CCCA">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-1_LoD2</gml:name>
      <bldg:class>1130</bldg:class>
      <bldg:yearOfConstruction>1905</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2053</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">11.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">3.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_D1127B2A-B7E7-482A-9AB1-6117DDE9FFE2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">16.0 0.0 0.0 10.0 0.0 0.0 10.0 8.0 0.0 16.0 8.0 0.0 16.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_85A6DD95-2BB6-4B7F-B11E-29AE6DAE4014">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">10.0 0.0 0.0 16.0 0.0 0.0 16.0 0.0 7.0 13.0 0.0 11.0 10.0 0.0 7.0 10.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_A018227E-273E-4078-BE3B-5E6E95605CF8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">16.0 8.0 0.0 10.0 8.0 0.0 10.0 8.0 7.0 13.0 8.0 11.0 16.0 8.0 7.0 16.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_FA67FF27-18CB-4609-8B42-8C78A496416B">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">10.0 0.0 0.0 10.0 0.0 7.0 10.0 8.0 7.0 10.0 8.0 0.0 10.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_AC4B6BC3-F693-406F-8463-1A05C96EBF52">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">16.0 8.0 0.0 16.0 8.0 7.0 16.0 0.0 7.0 16.0 0.0 0.0 16.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_C9FA006B-AE85-4A00-B73A-260DA4812839">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">10.0 0.0 7.0 13.0 0.0 11.0 13.0 8.0 11.0 10.0 8.0 7.0 10.0 0.0
                        7.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_637B2F68-6B84-480B-9CB1-50F75A496FB2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">16.0 8.0 7.0 13.0 8.0 11.0 13.0 0.0 11.0 16.0 0.0 7.0 16.0 8.0
                        7.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_56B0191A-411F-4367-A743-059FAC0BB8E1">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-2_LoD2</gml:name>
      <bldg:class>1160</bldg:class>
      <bldg:yearOfConstruction>1906</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2096</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">9.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">3.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_F7D82F0D-13E8-4DCE-9BA8-B481068B0749">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">26.0 0.0 0.0 20.0 0.0 0.0 20.0 8.0 0.0 26.0 8.0 0.0 26.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_AFC19DDA-B6E8-4FCC-94D8-528D1AA13D8C">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">20.0 0.0 0.0 26.0 0.0 0.0 26.0 0.0 7.0 23.0 0.0 9.0 20.0 0.0 7.0 20.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_5B73EEEF-AFB6-4975-B84B-B93483EDC1AF">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">26.0 8.0 0.0 20.0 8.0 0.0 20.0 8.0 7.0 23.0 8.0 9.0 26.0 8.0 7.0 26.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_69326D59-9D4D-46AA-ADB0-1E56ECCECC73">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">20.0 0.0 0.0 20.0 0.0 7.0 20.0 8.0 7.0 20.0 8.0 0.0 20.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_EC386BBB-62CC-4BC0-9E56-3467BCC9FB86">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">26.0 8.0 0.0 26.0 8.0 7.0 26.0 0.0 7.0 26.0 0.0 0.0 26.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_4D834F22-4E18-43DB-8076-279498006986">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">20.0 0.0 7.0 23.0 0.0 9.0 23.0 8.0 9.0 20.0 8.0 7.0 20.0 0.0 7.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_6ECFE9E9-AAAA-4BF9-9AB4-02F913EEDD5A">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">26.0 8.0 7.0 23.0 8.0 9.0 23.0 0.0 9.0 26.0 0.0 7.0 26.0 8.0 7.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_1E831EA2-F336-4D27-92E0-593D0D9D71D8">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-3_LoD2</gml:name>
      <bldg:class>1110</bldg:class>
      <bldg:yearOfConstruction>1947</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2044</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">11.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>3</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">3.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_63A69E16-B1E4-4732-89C3-B17E2987A631">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">36.0 0.0 0.0 30.0 0.0 0.0 30.0 8.0 0.0 36.0 8.0 0.0 36.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_A1583CB2-03B2-4B88-BF54-957494EDF9F3">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">30.0 0.0 0.0 36.0 0.0 0.0 36.0 0.0 3.0 33.0 0.0 11.0 30.0 0.0 3.0 30.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_300A6EF8-156E-4538-9A89-E7BE5C3170EA">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">36.0 8.0 0.0 30.0 8.0 0.0 30.0 8.0 3.0 33.0 8.0 11.0 36.0 8.0 3.0 36.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_6FA600BD-3DEE-4A04-B28A-C51528EE63AE">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">30.0 0.0 0.0 30.0 0.0 3.0 30.0 8.0 3.0 30.0 8.0 0.0 30.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_CE1F4E44-D5A9-4325-87FB-B2B381A81822">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">36.0 8.0 0.0 36.0 8.0 3.0 36.0 0.0 3.0 36.0 0.0 0.0 36.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_0A9AC6C7-496A-4B07-9D43-9DEB27655A5A">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">30.0 0.0 3.0 33.0 0.0 11.0 33.0 8.0 11.0 30.0 8.0 3.0 30.0 0.0
                        3.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_FB3F2FBE-468B-4D63-991A-0FCB8A7FF9DE">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">36.0 8.0 3.0 33.0 8.0 11.0 33.0 0.0 11.0 36.0 0.0 3.0 36.0 8.0
                        3.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_059E77E8-A50B-45DF-A5D5-7F09D32C09E1">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-4_LoD2</gml:name>
      <bldg:class>1150</bldg:class>
      <bldg:yearOfConstruction>1982</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2067</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">9.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">3.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_1E6BFAB6-0292-4013-BE90-A5FC4D35F062">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">46.0 0.0 0.0 40.0 0.0 0.0 40.0 8.0 0.0 46.0 8.0 0.0 46.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_A8A052B1-551D-4785-B417-37645B509C0F">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">40.0 0.0 0.0 46.0 0.0 0.0 46.0 0.0 4.0 43.0 0.0 9.0 40.0 0.0 4.0 40.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_2E6F861D-7E00-44D5-944F-719421E68046">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">46.0 8.0 0.0 40.0 8.0 0.0 40.0 8.0 4.0 43.0 8.0 9.0 46.0 8.0 4.0 46.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_199E49A8-0958-4FD8-913F-C63C343B01D1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">40.0 0.0 0.0 40.0 0.0 4.0 40.0 8.0 4.0 40.0 8.0 0.0 40.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_459DE3E8-D100-4F2F-8441-A894A98E6370">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">46.0 8.0 0.0 46.0 8.0 4.0 46.0 0.0 4.0 46.0 0.0 0.0 46.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_B1D569F7-1B6F-444B-AA9B-ACCB82B9106E">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">40.0 0.0 4.0 43.0 0.0 9.0 43.0 8.0 9.0 40.0 8.0 4.0 40.0 0.0 4.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_7E1FE9D0-2B81-4E04-90D6-F3D8FAA7DE14">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">46.0 8.0 4.0 43.0 8.0 9.0 43.0 0.0 9.0 46.0 0.0 4.0 46.0 8.0 4.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_42F189C9-6272-4E93-9A82-89C22A354602">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-5_LoD2</gml:name>
      <bldg:class>1180</bldg:class>
      <bldg:yearOfConstruction>1924</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2063</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">9.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">3.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_8990E696-DFA7-4A26-ADE8-BD9CD8CAC957">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">56.0 0.0 0.0 50.0 0.0 0.0 50.0 8.0 0.0 56.0 8.0 0.0 56.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_7725EAEB-6482-430F-B137-8435FAC5D60D">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">50.0 0.0 0.0 56.0 0.0 0.0 56.0 0.0 6.0 53.0 0.0 9.0 50.0 0.0 6.0 50.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_AD3F73E3-558C-4A89-88C5-9CE57D8B8F11">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">56.0 8.0 0.0 50.0 8.0 0.0 50.0 8.0 6.0 53.0 8.0 9.0 56.0 8.0 6.0 56.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_2C8A2909-A238-47B9-AB48-7B2EF6BF2B90">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">50.0 0.0 0.0 50.0 0.0 6.0 50.0 8.0 6.0 50.0 8.0 0.0 50.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_FE3DC57C-1960-48FF-933C-A48E1E9A5AE6">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">56.0 8.0 0.0 56.0 8.0 6.0 56.0 0.0 6.0 56.0 0.0 0.0 56.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_62CE9E76-371B-4007-B40C-2DE45D106789">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">50.0 0.0 6.0 53.0 0.0 9.0 53.0 8.0 9.0 50.0 8.0 6.0 50.0 0.0 6.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_F540317B-12BA-4E06-9470-663375F83E8E">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">56.0 8.0 6.0 53.0 8.0 9.0 53.0 0.0 9.0 56.0 0.0 6.0 56.0 8.0 6.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_1F989DA8-A234-4D78-B403-3D82AE473984">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-6_LoD2</gml:name>
      <bldg:class>1100</bldg:class>
      <bldg:yearOfConstruction>1910</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2028</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">11.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>5</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">2.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_3E2D2A4E-EA28-4740-A379-CF2FC515B7EB">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">66.0 0.0 0.0 60.0 0.0 0.0 60.0 8.0 0.0 66.0 8.0 0.0 66.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_20527D1D-3746-49C8-88D2-926A6974EEE7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">60.0 0.0 0.0 66.0 0.0 0.0 66.0 0.0 3.0 63.0 0.0 11.0 60.0 0.0 3.0 60.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_33C7E789-9DCE-4D91-8597-A79D9A1F69E1">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">66.0 8.0 0.0 60.0 8.0 0.0 60.0 8.0 3.0 63.0 8.0 11.0 66.0 8.0 3.0 66.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_47581DA5-6142-485C-88DA-821C069DA7F2">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">60.0 0.0 0.0 60.0 0.0 3.0 60.0 8.0 3.0 60.0 8.0 0.0 60.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_FE0E34E7-8C27-4224-8695-51BE014C7C48">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">66.0 8.0 0.0 66.0 8.0 3.0 66.0 0.0 3.0 66.0 0.0 0.0 66.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_5CE42DCB-A49D-4887-968B-D5B23CB5B60C">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">60.0 0.0 3.0 63.0 0.0 11.0 63.0 8.0 11.0 60.0 8.0 3.0 60.0 0.0
                        3.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_7AB65419-BB87-442B-8BE3-7F911807B410">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">66.0 8.0 3.0 63.0 8.0 11.0 63.0 0.0 11.0 66.0 0.0 3.0 66.0 8.0
                        3.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_D1598D54-4C5E-44BD-9D64-5F80CFF78666">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-7_LoD2</gml:name>
      <bldg:class>1070</bldg:class>
      <bldg:yearOfConstruction>1930</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2096</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">8.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">2.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_1B51CFEE-CF24-45B8-BB3F-8A9EECEBA016">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">76.0 0.0 0.0 70.0 0.0 0.0 70.0 8.0 0.0 76.0 8.0 0.0 76.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_0FD127DA-F062-42D8-9905-B5BF7FADA617">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">70.0 0.0 0.0 76.0 0.0 0.0 76.0 0.0 4.0 73.0 0.0 8.0 70.0 0.0 4.0 70.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_226FD408-7262-415F-BA21-725843150951">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">76.0 8.0 0.0 70.0 8.0 0.0 70.0 8.0 4.0 73.0 8.0 8.0 76.0 8.0 4.0 76.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_27D1995D-1BFB-4502-8BB3-EDC689FC225B">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">70.0 0.0 0.0 70.0 0.0 4.0 70.0 8.0 4.0 70.0 8.0 0.0 70.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_67170B23-4BC4-4750-8828-395E17AE64F9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">76.0 8.0 0.0 76.0 8.0 4.0 76.0 0.0 4.0 76.0 0.0 0.0 76.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_A17A5577-6AD2-47E5-8C49-B8F6AB98FA48">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">70.0 0.0 4.0 73.0 0.0 8.0 73.0 8.0 8.0 70.0 8.0 4.0 70.0 0.0 4.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_C3A1F70E-60E9-4D4F-BA4B-4A9C378D3E5B">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">76.0 8.0 4.0 73.0 8.0 8.0 73.0 0.0 8.0 76.0 0.0 4.0 76.0 8.0 4.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_E5657F8A-6B1E-4A35-9656-E844234B4F82">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-8_LoD2</gml:name>
      <bldg:class>1030</bldg:class>
      <bldg:yearOfConstruction>1965</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2053</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">9.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>2</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">3.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_7328D60F-7D1F-40C9-9277-50534C6CFFB4">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">86.0 0.0 0.0 80.0 0.0 0.0 80.0 8.0 0.0 86.0 8.0 0.0 86.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_0CD657E5-9C00-49D1-8CB4-5CDAAA137036">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">80.0 0.0 0.0 86.0 0.0 0.0 86.0 0.0 3.0 83.0 0.0 9.0 80.0 0.0 3.0 80.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_AAC4B6F9-244D-4479-A00C-715D1AED75B9">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">86.0 8.0 0.0 80.0 8.0 0.0 80.0 8.0 3.0 83.0 8.0 9.0 86.0 8.0 3.0 86.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_E783D3B7-A324-47CF-AB8C-687EA0F67A80">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">80.0 0.0 0.0 80.0 0.0 3.0 80.0 8.0 3.0 80.0 8.0 0.0 80.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_4A859117-1349-41A9-A561-8A156A9591B8">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">86.0 8.0 0.0 86.0 8.0 3.0 86.0 0.0 3.0 86.0 0.0 0.0 86.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_9673ADA8-4BF1-460E-9D8B-3F4881D0E388">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">80.0 0.0 3.0 83.0 0.0 9.0 83.0 8.0 9.0 80.0 8.0 3.0 80.0 0.0 3.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_BFA323C2-B8C2-4D85-802B-53DCCF50A331">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">86.0 8.0 3.0 83.0 8.0 9.0 83.0 0.0 9.0 86.0 0.0 3.0 86.0 8.0 3.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
  <cityObjectMember>
    <bldg:Building gml:id="FZK_GUID_ECB905FD-3514-4CEE-AFF2-A22E5A4AB3EF">
      <gml:description>FZK/IAI TestCases Only</gml:description>
      <gml:name>Testcase-0-9_LoD2</gml:name>
      <bldg:class>1040</bldg:class>
      <bldg:yearOfConstruction>1919</bldg:yearOfConstruction>
      <bldg:yearOfDemolition>2067</bldg:yearOfDemolition>
      <bldg:roofType>1030</bldg:roofType>
      <bldg:measuredHeight uom="#m">9.0</bldg:measuredHeight>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:storeysBelowGround>0</bldg:storeysBelowGround>
      <bldg:storeyHeightsAboveGround uom="#m">2.0</bldg:storeyHeightsAboveGround>
      <bldg:storeyHeightsBelowGround uom="#m">0.0</bldg:storeyHeightsBelowGround>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="FZK_GUID_D4C89A5A-9A5A-4462-BDE7-B3B576804255">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">96.0 0.0 0.0 90.0 0.0 0.0 90.0 8.0 0.0 96.0 8.0 0.0 96.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_964EDD1F-D70B-47E8-8E37-D1F51F72DD15">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">90.0 0.0 0.0 96.0 0.0 0.0 96.0 0.0 6.0 93.0 0.0 9.0 90.0 0.0 6.0 90.0 0.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_DF49F54D-292E-491E-83DF-B272BDB8BB48">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">96.0 8.0 0.0 90.0 8.0 0.0 90.0 8.0 6.0 93.0 8.0 9.0 96.0 8.0 6.0 96.0 8.0
                        0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_749A9CFF-0582-434C-A739-9AAD417CC434">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">90.0 0.0 0.0 90.0 0.0 6.0 90.0 8.0 6.0 90.0 8.0 0.0 90.0 0.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="FZK_GUID_D33796EF-F6B6-456D-A79D-897A72C20577">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">96.0 8.0 0.0 96.0 8.0 6.0 96.0 0.0 6.0 96.0 0.0 0.0 96.0 8.0 0.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_C3C02E91-66DC-4D44-975F-C15F2F7C2413">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">90.0 0.0 6.0 93.0 0.0 9.0 93.0 8.0 9.0 90.0 8.0 6.0 90.0 0.0 6.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="FZK_GUID_81823C4E-BE33-47B5-98F9-5913C8E432C7">
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon>
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList srsDimension="3">96.0 8.0 6.0 93.0 8.0 9.0 93.0 0.0 9.0 96.0 0.0 6.0 96.0 8.0 6.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </cityObjectMember>
</CityModel>
