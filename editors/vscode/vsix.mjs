// Reads a .vsix, which is a zip file: its central directory lists the entries, and each entry
// is stored or deflated (the only two methods vsce writes). Used by check-manifest.mjs and
// test-extension.mjs.
import { readFileSync } from 'node:fs';
import { inflateRawSync } from 'node:zlib';

export function readVsix(path) {
  const bytes = readFileSync(path);
  let end = -1;
  for (let i = bytes.length - 22; i >= Math.max(0, bytes.length - 22 - 65535); i--) {
    if (bytes.readUInt32LE(i) === 0x06054b50) {
      end = i;
      break;
    }
  }
  if (end < 0) throw new Error(`${path} is not a zip file (no end of central directory)`);
  const count = bytes.readUInt16LE(end + 10);
  let at = bytes.readUInt32LE(end + 16);
  const entries = new Map();
  for (let n = 0; n < count; n++) {
    if (bytes.readUInt32LE(at) !== 0x02014b50) throw new Error(`${path}: a damaged central directory`);
    const method = bytes.readUInt16LE(at + 10);
    const size = bytes.readUInt32LE(at + 20);
    const nameLength = bytes.readUInt16LE(at + 28);
    const extraLength = bytes.readUInt16LE(at + 30);
    const commentLength = bytes.readUInt16LE(at + 32);
    const local = bytes.readUInt32LE(at + 42);
    const name = bytes.toString('utf8', at + 46, at + 46 + nameLength);
    entries.set(name, { method, size, local });
    at += 46 + nameLength + extraLength + commentLength;
  }
  /** The bytes of one entry, or undefined when the .vsix has no such entry. */
  const bytesOf = (name) => {
    const e = entries.get(name);
    if (!e) return undefined;
    const data = e.local + 30 + bytes.readUInt16LE(e.local + 26) + bytes.readUInt16LE(e.local + 28);
    const raw = bytes.subarray(data, data + e.size);
    if (e.method === 0) return Buffer.from(raw);
    if (e.method === 8) return inflateRawSync(raw);
    throw new Error(`${name}: compression method ${e.method}`);
  };
  const read = (name) => {
    const b = bytesOf(name);
    return b === undefined ? undefined : b.toString('utf8');
  };
  return { names: [...entries.keys()], read, bytesOf };
}
