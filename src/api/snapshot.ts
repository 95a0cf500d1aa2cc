import { BroadPhase } from '../broad-phase/broad-phase';
import { DynamicTree } from '../broad-phase/dynamic-tree';
import { IntList } from '../broad-phase/int-list';
import { PairSet } from '../broad-phase/pair-set';
import { FulcrumError, fail } from '../core/errors';
import { JOINT_KINDS } from '../joints/registry';
import { ContactConstraints } from '../solver/contact-solver';
import { GraphColoring } from '../solver/graph-color';
import { Islands } from '../solver/island';
import { BodyStore } from '../store/body-store';
import { ContactStore } from '../store/contact-store';
import { EventBuffers } from '../store/event-buffers';
import { ShapeStore } from '../store/shape-store';
import { WorkingMemory, WorldCore } from '../world/world-core';
import { Body } from './body';
import { EventDispatcher } from './events';
import { WorldHandles } from './handles';
import { ShapeHandle } from './shape';
import {
  type AnyTypedArray,
  ByteReader,
  ByteWriter,
  CorruptSnapshot,
  fnv1a,
  isTypedArray,
  TAG_ARRAY,
  TAG_FALSE,
  TAG_FLOAT64,
  TAG_INT32,
  TAG_MAP,
  TAG_NULL,
  TAG_OBJECT,
  TAG_REF,
  TAG_SET,
  TAG_SKIP,
  TAG_STRING,
  TAG_TRUE,
  TAG_TYPED,
  TAG_UNDEFINED,
  typedArrayCode,
} from './snapshot-codec';

/**
 * World snapshots: `world.snapshot()` writes the whole engine state reachable from the World object,
 * generically: every own enumerable property of every object (sorted by name), typed arrays as raw
 * bytes, plain arrays, numbers with their exact bits, shared references and cycles kept. Nothing is
 * listed by hand, so columns added or renamed in the stores, the solver or the broad phase are
 * captured without touching this file. `World.restore(bytes)` builds a fresh World and writes the
 * state back into it, reusing the fresh objects (same class) and creating the ones the fresh world
 * does not have (handles, joints) from the classes below; stepping it is bit-identical to stepping
 * the original.
 *
 * The bytes depend on the world's history of steps and changes only: queries, shape tests, event
 * reads and debug drawing between steps keep their scratch outside the world (module scratch of the
 * query, tree and shape code), so that two peers with the same history compare snapshots byte for
 * byte (test/world/snapshot.test.ts runs a battery of them between steps).
 *
 * Bytes (little-endian):
 *   0   4  magic "FLCS"
 *   4   2  format version (SNAPSHOT_VERSION)
 *   6   2  reserved, 0
 *   8   4  build fingerprint: hash of the property layout of a fresh World (a snapshot restores only
 *          into the build that wrote it)
 *   12  4  payload length in bytes
 *   16  4  FNV-1a hash of the payload
 *   20  …  payload: the World object as one value of snapshot-codec.ts
 *
 * Not kept: event handlers (`world.on`); the sleep and wake events of the last step in `world.events`
 * (the contact, sensor and hit events are engine buffers: the restored world reads the same, less
 * those naming a shape destroyed between that step and the snapshot, which it has no handle for);
 * `userData` (of bodies, shapes and joints) unless it is plain data (numbers,
 * strings, booleans, null, plain objects and arrays, typed arrays, Map, Set of those): anything else,
 * e.g. a class instance or a function, becomes `undefined`. Functions held by engine objects are not
 * data: the fresh world's own are kept.
 */

const SNAPSHOT_MAGIC: readonly number[] = Object.freeze([0x46, 0x4c, 0x43, 0x53]); // "FLCS"
const SNAPSHOT_VERSION = 1;
const HEADER_SIZE = 20;

/**
 * Classes an object of the snapshot may have to be created as (the fresh world may not hold one):
 * stable names, independent of minification. Never rename a key (it is in the bytes). The joints'
 * come from the registry (each kind's className).
 */
const CLASSES: Readonly<Record<string, abstract new (...args: never[]) => object>> = Object.freeze({
  WorldHandles,
  Body,
  ShapeHandle,
  ...Object.fromEntries(Object.values(JOINT_KINDS).map((kind) => [kind.className, kind.jointClass])),
  WorldCore,
  BodyStore,
  ShapeStore,
  ContactStore,
  ContactConstraints,
  GraphColoring,
  Islands,
  EventBuffers,
  BroadPhase,
  DynamicTree,
  PairSet,
  IntList,
});

const CLASS_KEYS = new Map<unknown, string>(Object.entries(CLASSES).map(([key, ctor]) => [ctor, key]));

/**
 * Objects that are not state (event handlers; a world's WorkingMemory, written before every read):
 * written as SKIP, the fresh world keeps its own.
 */
function isExcluded(value: object): boolean {
  return value instanceof EventDispatcher || value instanceof WorkingMemory;
}

/** Properties whose value is the user's: kept only when plain data. */
const USER_KEYS: ReadonlySet<string> = new Set(['userData']);

/** '' for a plain object, 'null' for a null-prototype one, the class key otherwise. */
function classKey(value: object): string {
  const proto = Object.getPrototypeOf(value);
  if (proto === Object.prototype) return '';
  if (proto === null) return 'null';
  const ctor = (proto as { constructor?: unknown }).constructor;
  const key = CLASS_KEYS.get(ctor);
  if (key !== undefined) return key;
  return `?${typeof ctor === 'function' ? ctor.name : ''}`;
}

function isPlainData(value: unknown, seen: Set<object>): boolean {
  if (value === null) return true;
  const type = typeof value;
  if (type === 'function' || type === 'symbol' || type === 'bigint') return false;
  if (type !== 'object') return true;
  const obj = value as object;
  if (seen.has(obj)) return true;
  seen.add(obj);
  if (isTypedArray(obj)) return typedArrayCode(obj) >= 0;
  if (Array.isArray(obj)) return obj.every((x) => isPlainData(x, seen));
  if (obj instanceof Map) {
    for (const [k, v] of obj) if (!isPlainData(k, seen) || !isPlainData(v, seen)) return false;
    return true;
  }
  if (obj instanceof Set) {
    for (const v of obj) if (!isPlainData(v, seen)) return false;
    return true;
  }
  const key = classKey(obj);
  if (key !== '' && key !== 'null') return false;
  for (const k of Object.keys(obj)) if (!isPlainData((obj as Record<string, unknown>)[k], seen)) return false;
  return true;
}

class GraphWriter {
  private readonly ids = new Map<object, number>();

  constructor(private readonly out: ByteWriter) {}

  value(v: unknown): void {
    const out = this.out;
    switch (typeof v) {
      case 'undefined':
        out.u8(TAG_UNDEFINED);
        return;
      case 'boolean':
        out.u8(v ? TAG_TRUE : TAG_FALSE);
        return;
      case 'number':
        if ((v | 0) === v && !Object.is(v, -0)) {
          out.u8(TAG_INT32);
          out.i32(v);
        } else {
          out.u8(TAG_FLOAT64);
          out.f64(v);
        }
        return;
      case 'string':
        out.u8(TAG_STRING);
        out.string(v);
        return;
      case 'object':
        if (v === null) out.u8(TAG_NULL);
        else this.object(v);
        return;
      default:
        // functions, symbols, bigints: not data
        out.u8(TAG_SKIP);
    }
  }

  private object(v: object): void {
    const out = this.out;
    const id = this.ids.get(v);
    if (id !== undefined) {
      out.u8(TAG_REF);
      out.u32(id);
      return;
    }
    if (isExcluded(v)) {
      out.u8(TAG_SKIP);
      return;
    }
    if (isTypedArray(v)) {
      const code = typedArrayCode(v);
      if (code < 0) {
        out.u8(TAG_SKIP);
        return;
      }
      this.ids.set(v, this.ids.size);
      out.u8(TAG_TYPED);
      out.typed(v, code);
      return;
    }
    if (ArrayBuffer.isView(v) || v instanceof ArrayBuffer || v instanceof WeakMap || v instanceof WeakSet) {
      out.u8(TAG_SKIP);
      return;
    }
    this.ids.set(v, this.ids.size);
    if (Array.isArray(v)) {
      out.u8(TAG_ARRAY);
      out.u8(Object.isFrozen(v) ? 1 : 0);
      out.u32(v.length);
      for (let i = 0; i < v.length; i++) this.value(v[i]);
      return;
    }
    if (v instanceof Map) {
      out.u8(TAG_MAP);
      out.u32(v.size);
      for (const [key, value] of v) {
        this.value(key);
        this.value(value);
      }
      return;
    }
    if (v instanceof Set) {
      out.u8(TAG_SET);
      out.u32(v.size);
      for (const value of v) this.value(value);
      return;
    }
    out.u8(TAG_OBJECT);
    out.string(classKey(v));
    out.u8(Object.isFrozen(v) ? 1 : 0);
    const record = v as Record<string, unknown>;
    const keys = Object.keys(record).sort();
    out.u32(keys.length);
    for (const key of keys) {
      out.string(key);
      const value = record[key];
      if (USER_KEYS.has(key) && !isPlainData(value, new Set())) this.value(undefined);
      else this.value(value);
    }
  }
}

/** A value that leaves the reader's existing one in place. */
const SKIP = Symbol('skip');

function isReusable(existing: unknown): existing is object {
  return typeof existing === 'object' && existing !== null && !Object.isFrozen(existing);
}

class GraphReader {
  private readonly objects: unknown[] = [];

  constructor(private readonly r: ByteReader) {}

  /** Reads one value; objects are written into `existing` when it has the same kind and class. */
  value(existing: unknown): unknown {
    const r = this.r;
    const tag = r.u8();
    switch (tag) {
      case TAG_UNDEFINED:
        return undefined;
      case TAG_NULL:
        return null;
      case TAG_FALSE:
        return false;
      case TAG_TRUE:
        return true;
      case TAG_INT32:
        return r.i32();
      case TAG_FLOAT64:
        return r.f64();
      case TAG_STRING:
        return r.string();
      case TAG_SKIP:
        return SKIP;
      case TAG_REF: {
        const id = r.u32();
        if (id >= this.objects.length) throw new CorruptSnapshot(`bad object reference ${id}`);
        return this.objects[id];
      }
      case TAG_TYPED: {
        const value: AnyTypedArray = r.typed();
        this.objects.push(value);
        return value;
      }
      case TAG_ARRAY:
        return this.array(existing);
      case TAG_MAP:
      case TAG_SET:
        return this.collection(tag, existing);
      case TAG_OBJECT:
        return this.object(existing);
      default:
        throw new CorruptSnapshot(`bad tag ${tag}`);
    }
  }

  private count(): number {
    const n = this.r.u32();
    // every element takes at least one byte: a larger count cannot be right
    if (n > this.r.remaining) throw new CorruptSnapshot('truncated data');
    return n;
  }

  private array(existing: unknown): unknown[] {
    const frozen = this.r.u8() !== 0;
    const n = this.count();
    const array: unknown[] = Array.isArray(existing) && isReusable(existing) ? existing : [];
    this.objects.push(array);
    array.length = n;
    for (let i = 0; i < n; i++) {
      const value = this.value(array[i]);
      if (value !== SKIP) array[i] = value;
    }
    if (frozen) Object.freeze(array);
    return array;
  }

  private collection(tag: number, existing: unknown): Map<unknown, unknown> | Set<unknown> {
    const n = this.count();
    if (tag === TAG_MAP) {
      const map = existing instanceof Map && isReusable(existing) ? existing : new Map();
      map.clear();
      this.objects.push(map);
      for (let i = 0; i < n; i++) {
        const key = this.value(undefined);
        const value = this.value(undefined);
        if (key !== SKIP && value !== SKIP) map.set(key, value);
      }
      return map;
    }
    const set = existing instanceof Set && isReusable(existing) ? existing : new Set();
    set.clear();
    this.objects.push(set);
    for (let i = 0; i < n; i++) {
      const value = this.value(undefined);
      if (value !== SKIP) set.add(value);
    }
    return set;
  }

  private object(existing: unknown): object {
    const r = this.r;
    const key = r.string();
    const frozen = r.u8() !== 0;
    let obj: Record<string, unknown>;
    if (
      isReusable(existing) &&
      !Array.isArray(existing) &&
      !ArrayBuffer.isView(existing) &&
      !(existing instanceof Map) &&
      !(existing instanceof Set) &&
      classKey(existing) === key
    ) {
      obj = existing as Record<string, unknown>;
    } else if (key === '') {
      obj = {};
    } else if (key === 'null') {
      obj = Object.create(null);
    } else {
      const ctor = Object.hasOwn(CLASSES, key) ? CLASSES[key] : undefined;
      if (ctor === undefined) throw new CorruptSnapshot(`cannot create an object of class ${key}`);
      obj = Object.create(ctor.prototype);
    }
    this.objects.push(obj);
    const n = this.count();
    for (let i = 0; i < n; i++) {
      const name = r.string();
      const value = this.value(Object.hasOwn(obj, name) ? obj[name] : undefined);
      if (value === SKIP) continue;
      if (name === '__proto__') {
        Object.defineProperty(obj, name, { value, writable: true, enumerable: true, configurable: true });
      } else {
        obj[name] = value;
      }
    }
    if (frozen) Object.freeze(obj);
    return obj;
  }
}

/** Hash of the property layout (classes, names, kinds, not values) of an object graph. */
function layoutHash(root: object): number {
  const parts: string[] = [];
  const seen = new Set<object>();
  const visit = (v: unknown): void => {
    if (typeof v !== 'object' || v === null) {
      parts.push(typeof v === 'function' ? 'f' : 'p');
      return;
    }
    if (seen.has(v)) {
      parts.push('@');
      return;
    }
    seen.add(v);
    if (isExcluded(v)) parts.push('x');
    else if (isTypedArray(v)) parts.push(`t${typedArrayCode(v)}`);
    else if (Array.isArray(v)) {
      parts.push(`[${v.length}`);
      for (const x of v) visit(x);
      parts.push(']');
    } else if (v instanceof Map || v instanceof Set) parts.push('m');
    else {
      parts.push(`{${classKey(v)}`);
      const record = v as Record<string, unknown>;
      for (const key of Object.keys(record).sort()) {
        parts.push(key);
        visit(record[key]);
      }
      parts.push('}');
    }
  };
  visit(root);
  return fnv1a(new TextEncoder().encode(parts.join(',')));
}

let fingerprint: number | undefined;

/** The build fingerprint, from a fresh world made by `makeFresh` (computed once). */
function buildFingerprint(makeFresh: () => object): number {
  if (fingerprint === undefined) fingerprint = layoutHash(makeFresh());
  return fingerprint;
}

/** Writes the snapshot of a world (see the format above). */
export function writeSnapshot(world: object, makeFresh: () => object): Uint8Array {
  const out = new ByteWriter();
  for (const byte of SNAPSHOT_MAGIC) out.u8(byte);
  out.u16(SNAPSHOT_VERSION);
  out.u16(0);
  out.u32(buildFingerprint(makeFresh));
  out.u32(0); // payload length, patched below
  out.u32(0); // payload hash, patched below
  new GraphWriter(out).value(world);
  const bytes = out.result();
  const view = new DataView(bytes.buffer);
  view.setUint32(12, bytes.length - HEADER_SIZE, true);
  view.setUint32(16, fnv1a(bytes, HEADER_SIZE), true);
  return bytes;
}

function corrupt(reason: string): never {
  throw new FulcrumError(`bytes is not a valid Fulcrum snapshot: ${reason}`);
}

/**
 * Checks `bytes` and writes the state it holds into `fresh`, a newly constructed world (made by
 * `makeFresh`, with no bodies yet). Throws FulcrumError naming `bytes` when it is not a snapshot of
 * this build.
 */
export function readSnapshot(bytes: unknown, fresh: object, makeFresh: () => object): void {
  if (!(bytes instanceof Uint8Array)) fail('bytes', bytes, 'a Uint8Array made by world.snapshot()');
  if (bytes.length < HEADER_SIZE) corrupt(`truncated (${bytes.length} bytes)`);
  for (let i = 0; i < SNAPSHOT_MAGIC.length; i++) {
    if (bytes[i] !== SNAPSHOT_MAGIC[i]) corrupt('wrong magic number');
  }
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const version = view.getUint16(4, true);
  if (version !== SNAPSHOT_VERSION) {
    corrupt(`unsupported format version ${version} (this build reads version ${SNAPSHOT_VERSION})`);
  }
  // a later format may give these bytes a meaning: this one refuses what it cannot read
  if (view.getUint16(6, true) !== 0) corrupt('the reserved header bytes 6-7 are not 0');
  if (view.getUint32(8, true) !== buildFingerprint(makeFresh)) {
    corrupt('it was written by a different build of Fulcrum');
  }
  const length = view.getUint32(12, true);
  if (bytes.length - HEADER_SIZE !== length) {
    corrupt(
      bytes.length - HEADER_SIZE < length
        ? `truncated (${bytes.length} of ${HEADER_SIZE + length} bytes)`
        : `${bytes.length - HEADER_SIZE - length} extra bytes at the end`,
    );
  }
  if (fnv1a(bytes, HEADER_SIZE) !== view.getUint32(16, true)) corrupt('the data is damaged (bad checksum)');
  const reader = new ByteReader(bytes, HEADER_SIZE, bytes.length);
  let root: unknown;
  try {
    root = new GraphReader(reader).value(fresh);
    if (!reader.done) throw new CorruptSnapshot('extra data after the world');
  } catch (e) {
    // a checksummed snapshot of this build always reads: anything thrown means made-up bytes
    corrupt(e instanceof Error ? e.message : String(e));
  }
  if (root !== fresh) corrupt('it does not hold a World');
}
