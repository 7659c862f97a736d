#!/usr/bin/env node
// A simulated MAVLink 2 autopilot for Photoflight's upload tests, written with the node-mavlink
// package (an implementation independent of Photoflight's own core/mavlink). It speaks the mission
// protocol as a vehicle: accepts uploads of the mission, geofence and rally plans (MISSION_COUNT,
// asks with MISSION_REQUEST_INT or the older MISSION_REQUEST, re-asks on a timeout or a repeated
// item, MISSION_ACK), answers downloads (MISSION_REQUEST_LIST), sends a heartbeat every second, and
// can be told to lose or refuse messages. It runs on loopback only and stops by itself.
//
//   node sim_vehicle.mjs [--udp PORT | --udp-out HOST:PORT | --tcp PORT] [--sysid N]
//        [--autopilot ardupilot|px4] [--home LAT,LON] [--drop-request SEQ] [--nack SEQ:CODE]
//        [--nack-type mission|fence|rally] [--old-requests] [--silent] [--seconds N]
//        [--report FILE] [--vehicle-timeout MS] [--delay MS] [--vehicle-type N]
//
// --udp 0 / --tcp 0 pick a free port. Once listening it prints "READY <port>" on stdout.
// --drop-request SEQ  the first request for mission item SEQ is never sent (a lost message)
// --nack SEQ:CODE     item SEQ of the upload is answered with MISSION_ACK of result CODE
// --home LAT,LON      ArduPilot style: mission item 0 reads back as this home position
// --report FILE       the plans held, as JSON, rewritten after every accepted upload
// --vehicle-timeout MS  how long the vehicle waits for an item before it asks again (3000)
// --delay MS          every message leaves the vehicle MS later (a slow link)
// --vehicle-type N    the heartbeat's MAV_TYPE (2 quadrotor, the default; 1 fixed wing; 22 VTOL)
//
// Quirks of node-mavlink 2.3.0 worked around here: its MAVLink 1 serializer writes the MAVLink 2
// extension fields (so only MAVLink 2 is sent); an all-zero MAVLink 2 payload is cut to 0 bytes where
// the reference C library keeps one (fixed below); send() defaults to MAVLink 1 with one global
// sequence counter (not used: each vehicle counts its own); uint64 fields need BigInt (none used).
import dgram from 'node:dgram';
import fs from 'node:fs';
import net from 'node:net';
import { PassThrough } from 'node:stream';
import {
  MavLinkPacketSplitter, MavLinkPacketParser, MavLinkProtocolV2, minimal, common, x25crc,
} from 'node-mavlink';

const REGISTRY = { ...minimal.REGISTRY, ...common.REGISTRY };
const TYPES = { 0: 'mission', 1: 'fence', 2: 'rally' };

function parseArgs(argv) {
  const o = { sysid: 1, autopilot: 'ardupilot', seconds: 60, nackType: 0, vehicleTimeout: 3000, vehicleType: 2 };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const next = () => {
      if (i + 1 >= argv.length) throw new Error(`${a} needs a value`);
      return argv[++i];
    };
    switch (a) {
      case '--udp': o.udp = Number(next()); break;
      case '--udp-out': o.udpOut = next(); break;
      case '--tcp': o.tcp = Number(next()); break;
      case '--sysid': o.sysid = Number(next()); break;
      case '--autopilot': o.autopilot = next(); break;
      case '--home': o.home = next().split(',').map(Number); break;
      case '--drop-request': o.dropRequest = Number(next()); break;
      case '--nack': { const [s, c] = next().split(':').map(Number); o.nackSeq = s; o.nackCode = c; break; }
      case '--nack-type': { const t = next(); o.nackType = Number(Object.keys(TYPES).find((k) => TYPES[k] === t)); break; }
      case '--old-requests': o.oldRequests = true; break;
      case '--silent': o.silent = true; break;
      case '--seconds': o.seconds = Number(next()); break;
      case '--report': o.report = next(); break;
      case '--vehicle-timeout': o.vehicleTimeout = Number(next()); break;
      case '--delay': o.delay = Number(next()); break;
      case '--vehicle-type': o.vehicleType = Number(next()); break;
      default: throw new Error(`unknown option ${a}`);
    }
  }
  if (o.udp === undefined && o.udpOut === undefined && o.tcp === undefined) o.udp = 0;
  return o;
}

const opt = parseArgs(process.argv.slice(2));
const protocol = new MavLinkProtocolV2(opt.sysid, 1);
let seq = 0;
let output = () => {};

// MAVLink 2 bytes of a message; an empty payload keeps one zero byte as the reference library does.
function frame(msg) {
  let buf = protocol.serialize(msg, seq);
  seq = (seq + 1) & 0xff;
  if (buf.readUInt8(1) === 0) {
    const fixed = Buffer.alloc(buf.length + 1);
    buf.copy(fixed, 0, 0, MavLinkProtocolV2.PAYLOAD_OFFSET);
    fixed.writeUInt8(1, 1);
    fixed.writeUInt8(0, MavLinkProtocolV2.PAYLOAD_OFFSET);
    const crc = x25crc(fixed, 1, 2, msg.constructor.MAGIC_NUMBER);
    fixed.writeUInt16LE(crc, fixed.length - 2);
    buf = fixed;
  }
  return buf;
}

function send(msg) {
  if (opt.silent) return;
  const buf = frame(msg);
  if (opt.delay > 0) setTimeout(() => output(buf), opt.delay); // a slow radio link; order is kept
  else output(buf);
}

// firstCountAt / lastRequestAt: when (ms since the epoch) the ground station began uploading and last
// asked for an item, to see that two vehicles were served at the same time.
const stats = {
  requests: 0, resentRequests: 0, repeatedItems: 0, nacks: 0, downloads: 0, gcs: null,
  firstCountAt: 0, lastRequestAt: 0,
};
const plans = { 0: [], 1: [], 2: [] };
let upload = null; // { type, count, items, peer, timer, tries }

function writeReport() {
  if (!opt.report) return;
  const json = {
    sysid: opt.sysid, stats,
    mission: plans[0], fence: plans[1], rally: plans[2],
  };
  fs.writeFileSync(`${opt.report}.part`, JSON.stringify(json, null, 1));
  fs.renameSync(`${opt.report}.part`, opt.report);
}

function ack(type, result, peer) {
  const m = new common.MissionAck();
  m.targetSystem = peer.sysid;
  m.targetComponent = peer.compid;
  m.type = result;
  m.missionType = type;
  send(m);
}

function request(seqNo) {
  if (seqNo === opt.dropRequest && upload.type === 0) {
    opt.dropRequest = undefined; // lost on the way: the GCS must recover
    armUploadTimer();
    return;
  }
  const m = opt.oldRequests ? new common.MissionRequest() : new common.MissionRequestInt();
  m.targetSystem = upload.peer.sysid;
  m.targetComponent = upload.peer.compid;
  m.seq = seqNo;
  m.missionType = upload.type;
  stats.requests++;
  send(m);
  armUploadTimer();
}

// The vehicle's side of the protocol's timeout: ask again, give up after a few tries.
function armUploadTimer() {
  clearTimeout(upload.timer);
  upload.timer = setTimeout(() => {
    if (!upload) return;
    if (++upload.tries > 5) { upload = null; return; }
    stats.resentRequests++;
    const again = upload.items.length;
    const m = opt.oldRequests ? new common.MissionRequest() : new common.MissionRequestInt();
    m.targetSystem = upload.peer.sysid;
    m.targetComponent = upload.peer.compid;
    m.seq = again;
    m.missionType = upload.type;
    send(m);
    armUploadTimer();
  }, opt.vehicleTimeout);
}

function itemOf(data, asFloat) {
  return {
    seq: data.seq, frame: data.frame, command: data.command, current: data.current,
    autocontinue: data.autocontinue,
    params: [data.param1, data.param2, data.param3, data.param4],
    x: asFloat ? Math.round(data.x * 1e7) : data.x,
    y: asFloat ? Math.round(data.y * 1e7) : data.y,
    z: data.z,
  };
}

function sendItem(type, seqNo, peer, asInt) {
  const it = plans[type][seqNo];
  if (!it) return;
  const m = asInt ? new common.MissionItemInt() : new common.MissionItem();
  m.targetSystem = peer.sysid;
  m.targetComponent = peer.compid;
  m.seq = seqNo;
  m.frame = it.frame;
  m.command = it.command;
  m.current = 0;
  m.autocontinue = it.autocontinue;
  [m.param1, m.param2, m.param3, m.param4] = it.params;
  let { x, y } = it;
  if (type === 0 && seqNo === 0 && opt.home) {
    x = Math.round(opt.home[0] * 1e7);
    y = Math.round(opt.home[1] * 1e7);
  }
  m.x = asInt ? x : x / 1e7;
  m.y = asInt ? y : y / 1e7;
  m.z = it.z;
  m.missionType = type;
  send(m);
}

function onPacket(packet) {
  const clazz = REGISTRY[packet.header.msgid];
  if (!clazz) return;
  const data = packet.protocol.data(packet.payload, clazz);
  const peer = { sysid: packet.header.sysid, compid: packet.header.compid };
  const forMe = (d) => d.targetSystem === opt.sysid || d.targetSystem === 0;
  switch (clazz) {
    case minimal.Heartbeat:
      if (data.type === 6) stats.gcs = peer; // MAV_TYPE_GCS
      break;
    case common.MissionCount: {
      if (!forMe(data)) break;
      if (!stats.firstCountAt) stats.firstCountAt = Date.now();
      if (upload) clearTimeout(upload.timer);
      upload = { type: data.missionType, count: data.count, items: [], peer, tries: 0 };
      if (data.count === 0) {
        plans[upload.type] = [];
        ack(upload.type, 0, peer);
        upload = null;
        writeReport();
      } else {
        request(0);
      }
      break;
    }
    case common.MissionItemInt:
    case common.MissionItem: {
      if (!forMe(data) || !upload || data.missionType !== upload.type) break;
      const n = upload.items.length;
      if (data.seq === n - 1) { // our request for the next one was lost: the GCS repeated this one
        upload.tries = 0;
        stats.repeatedItems++;
        request(n);
        break;
      }
      if (data.seq !== n) break;
      if (data.seq === opt.nackSeq && upload.type === opt.nackType) {
        stats.nacks++;
        clearTimeout(upload.timer);
        ack(upload.type, opt.nackCode, peer);
        upload = null;
        break;
      }
      upload.items.push(itemOf(data, clazz === common.MissionItem));
      upload.tries = 0;
      if (upload.items.length < upload.count) {
        request(upload.items.length);
      } else {
        clearTimeout(upload.timer);
        plans[upload.type] = upload.items;
        ack(upload.type, 0, peer);
        if (upload.type === 0) {
          const t = new common.StatusText();
          t.severity = 6;
          t.text = 'Flight plan received';
          send(t);
        }
        upload = null;
        writeReport();
      }
      break;
    }
    case common.MissionRequestList:
      if (!forMe(data)) break;
      stats.downloads++;
      {
        const m = new common.MissionCount();
        m.targetSystem = peer.sysid;
        m.targetComponent = peer.compid;
        m.count = plans[data.missionType] ? plans[data.missionType].length : 0;
        m.missionType = data.missionType;
        send(m);
      }
      break;
    case common.MissionRequestInt:
    case common.MissionRequest:
      if (!forMe(data) || upload) break;
      stats.lastRequestAt = Date.now();
      sendItem(data.missionType, data.seq, peer, clazz === common.MissionRequestInt);
      break;
    default:
      break;
  }
}

const bytesIn = new PassThrough();
bytesIn.pipe(new MavLinkPacketSplitter()).pipe(new MavLinkPacketParser()).on('data', onPacket);

function heartbeat() {
  const hb = new minimal.Heartbeat();
  hb.type = opt.vehicleType; // MAV_TYPE: 2 quadrotor unless told
  hb.autopilot = opt.autopilot === 'px4' ? 12 : 3;
  hb.baseMode = 0;
  hb.customMode = 0;
  hb.systemStatus = 3; // MAV_STATE_STANDBY
  hb.mavlinkVersion = 3;
  send(hb);
}

function ready(port) {
  process.stdout.write(`READY ${port}\n`);
}

if (opt.tcp !== undefined) {
  const server = net.createServer((socket) => {
    output = (buf) => socket.write(buf);
    socket.on('data', (d) => bytesIn.write(d));
    socket.on('error', () => {});
  });
  server.listen(opt.tcp, '127.0.0.1', () => ready(server.address().port));
} else {
  const sock = dgram.createSocket('udp4');
  let gcs = null;
  if (opt.udpOut) {
    const [host, port] = opt.udpOut.split(':');
    gcs = { address: host, port: Number(port) };
  }
  output = (buf) => { if (gcs) sock.send(buf, gcs.port, gcs.address); };
  sock.on('message', (msg, rinfo) => {
    if (!opt.udpOut) gcs = rinfo; // answer where the ground station sends from
    bytesIn.write(msg);
  });
  sock.bind(opt.udpOut ? 0 : opt.udp, '127.0.0.1', () => ready(sock.address().port));
}

writeReport();
const hbTimer = setInterval(heartbeat, 1000);
heartbeat();
setTimeout(() => {
  clearInterval(hbTimer);
  writeReport();
  process.exit(0);
}, opt.seconds * 1000);
process.on('SIGTERM', () => { writeReport(); process.exit(0); });
