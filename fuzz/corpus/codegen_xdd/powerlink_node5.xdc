<?xml version="1.0" encoding="UTF-8"?>
<!-- fieldcodec test fixture: a configured CANopen node (XDC, CiA 311); hand-written -->
<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <ISO15745Profile>
    <ProfileHeader><ProfileIdentification>CANopen device profile</ProfileIdentification><ProfileRevision>1.1</ProfileRevision><ProfileName/><ProfileSource/><ProfileClassID>Device</ProfileClassID>
      <ISO15745Reference><ISO15745Part>1</ISO15745Part><ISO15745Edition>1</ISO15745Edition><ProfileTechnology>CANopen</ProfileTechnology></ISO15745Reference></ProfileHeader>
    <ProfileBody xsi:type="ProfileBody_Device_CANopen" fileName="node5.xdc">
      <DeviceIdentity><vendorName>Fixture</vendorName><productName>Drive</productName></DeviceIdentity>
    </ProfileBody>
  </ISO15745Profile>
  <ISO15745Profile>
    <ProfileHeader><ProfileIdentification>CANopen communication network profile</ProfileIdentification><ProfileRevision>1.1</ProfileRevision><ProfileName/><ProfileSource/><ProfileClassID>CommunicationNetwork</ProfileClassID>
      <ISO15745Reference><ISO15745Part>1</ISO15745Part><ISO15745Edition>1</ISO15745Edition><ProfileTechnology>CANopen</ProfileTechnology></ISO15745Reference></ProfileHeader>
    <ProfileBody xsi:type="ProfileBody_CommunicationNetwork_CANopen" fileName="node5.xdc">
      <ApplicationLayers>
        <CANopenObjectList>
          <CANopenObject index="1000" name="Device type" objectType="7" dataType="0007" accessType="ro" defaultValue="0x00020192"/>
          <CANopenObject index="1017" name="Producer heartbeat time" objectType="7" dataType="0006" accessType="rw" defaultValue="0" actualValue="250" denotation="heartbeat"/>
          <CANopenObject index="1018" name="Identity object" objectType="9" subNumber="2">
            <CANopenSubObject subIndex="00" name="Highest sub-index supported" objectType="7" dataType="0005" accessType="ro" defaultValue="1"/>
            <CANopenSubObject subIndex="01" name="Vendor-ID" objectType="7" dataType="0007" accessType="ro" defaultValue="0x00000099" actualValue="0x00000099"/>
          </CANopenObject>
          <CANopenObject index="1800" name="TPDO 1 communication" objectType="9" subNumber="2">
            <CANopenSubObject subIndex="00" name="Highest sub-index" objectType="7" dataType="0005" accessType="const" defaultValue="1"/>
            <CANopenSubObject subIndex="01" name="COB-ID" objectType="7" dataType="0007" accessType="rw" defaultValue="$NODEID+0x180" actualValue="0x80000185"/>
          </CANopenObject>
          <CANopenObject index="1A00" name="TPDO 1 mapping" objectType="9" subNumber="2">
            <CANopenSubObject subIndex="00" name="Number of entries" objectType="7" dataType="0005" accessType="rw" defaultValue="1"/>
            <CANopenSubObject subIndex="01" name="Mapping 1" objectType="7" dataType="0007" accessType="rw" defaultValue="0x60410010"/>
          </CANopenObject>
          <CANopenObject index="6041" name="Statusword" objectType="7" dataType="0006" accessType="ro" PDOmapping="TPDO"/>
        </CANopenObjectList>
      </ApplicationLayers>
      <TransportLayers/>
      <NetworkManagement>
        <CANopenGeneralFeatures granularity="8" nrOfTxPDO="1"/>
        <deviceCommissioning nodeID="5" nodeName="drive 5" actualBaudRate="500 Kbps" networkNumber="1" CANopenManager="false"/>
      </NetworkManagement>
    </ProfileBody>
  </ISO15745Profile>
</ISO15745ProfileContainer>
