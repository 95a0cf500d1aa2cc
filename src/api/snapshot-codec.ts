/**
 * Generic, deterministic binary encoding of an object graph, used by world snapshots (see snapshot.ts).
 *
 * A value is one tag byte followed by its data (little-endian):
 *
 *   UNDEFINED, NULL, FALSE, TRUE   no data
 *   INT32                          i32 (integers in int32 range, never -0)
 *   FLOAT64                        f64 (every other number, exact bits: -0, NaN, infinities)
 *   STRING                         string reference (see below)
 *   TYPED                          u8 element type, u32 element count, u32 stored byte count, the
 *                                  array's little-endian bytes up to its last non-zero byte (the rest
 *                                  are zeros)
 *   ARRAY                          u8 frozen, u32 length, then each element
 *   OBJECT                         string class key, u8 frozen, u32 property count, then per property
 *                                  (sorted by name) the name (string reference) and the value
 *   MAP / SET                      u32 entry count, then key and value / each value, in insertion order
 *   REF                            u32 object id: an object encoded earlier (shared references, cycles)
 *   SKIP                           not data (a function, an excluded object): the reader keeps its own
 *
 * Every typed array, array, object, map and set gets the next object id when first written; a second
 * reference to it is a REF. A string reference is a u32 index into the strings seen so far; the index
 * equal to the count of strings seen introduces a new string (u32 byte length, UTF-8 bytes).
 */

export const TAG_UNDEFINED = 0;
export const TAG_NULL = 1;
export const TAG_FALSE = 2;
export const TAG_TRUE = 3;
export const TAG_INT32 = 4;
export const TAG_FLOAT64 = 5;
export const TAG_STRING = 6;
export const TAG_TYPED = 7;
export const TAG_ARRAY = 8;
export const TAG_OBJECT = 9;
export const TAG_MAP = 10;
export const TAG_SET = 11;
export const TAG_REF = 12;
export const TAG_SKIP = 13;

type TypedArrayCtor =
  | Int8ArrayConstructor
  | Uint8ArrayConstructor
  | Uint8ClampedArrayConstructor
  | Int16ArrayConstructor
  | Uint16ArrayConstructor
  | Int32ArrayConstructor
  | Uint32ArrayConstructor
  | Float32ArrayConstructor
  | Float64ArrayConstructor
  | BigInt64ArrayConstructor
  | BigUint64ArrayConstructor;

export type AnyTypedArray = InstanceType<TypedArrayCtor>;

/** Element type codes of TYPED values: the index in this list. Never reorder (it is the format). */
const TYPED_ARRAY_TYPES: readonly TypedArrayCtor[] = [
  Int8Array,
  Uint8Array,
  Uint8ClampedArray,
  Int16Array,
  Uint16Array,
  Int32Array,
  Uint32Array,
  Float32Array,
  Float64Array,
  BigInt64Array,
  BigUint64Array,
];

export function isTypedArray(value: object): value is AnyTypedArray {
  return ArrayBuffer.isView(value) && !(value instanceof DataView);
}

export function typedArrayCode(value: AnyTypedArray): number {
  for (let i = 0; i < TYPED_ARRAY_TYPES.length; i++) {
    if (value.constructor === TYPED_ARRAY_TYPES[i]) return i;
  }
  return -1;
}

const LITTLE_ENDIAN = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

/** Reverses the bytes of each element in place (only on big-endian hosts). */
function swapBytes(bytes: Uint8Array, elementSize: number): void {
  for (let i = 0; i < bytes.length; i += elementSize) {
    for (let a = i, b = i + elementSize - 1; a < b; a++, b--) {
      const t = bytes[a];
      bytes[a] = bytes[b];
      bytes[b] = t;
    }
  }
}

/** A growable little-endian byte buffer. */
export class ByteWriter {
  private bytes = new Uint8Array(1024);
  private view = new DataView(this.bytes.buffer);
  length = 0;
  private readonly strings = new Map<string, number>();
  private readonly encoder = new TextEncoder();

  private reserve(n: number): void {
    if (this.length + n <= this.bytes.length) return;
    let capacity = this.bytes.length * 2;
    while (capacity < this.length + n) capacity *= 2;
    const bytes = new Uint8Array(capacity);
    bytes.set(this.bytes.subarray(0, this.length));
    this.bytes = bytes;
    this.view = new DataView(bytes.buffer);
  }

  u8(v: number): void {
    this.reserve(1);
    this.bytes[this.length++] = v;
  }

  u16(v: number): void {
    this.reserve(2);
    this.view.setUint16(this.length, v, true);
    this.length += 2;
  }

  u32(v: number): void {
    this.reserve(4);
    this.view.setUint32(this.length, v, true);
    this.length += 4;
  }

  i32(v: number): void {
    this.reserve(4);
    this.view.setInt32(this.length, v, true);
    this.length += 4;
  }

  f64(v: number): void {
    this.reserve(8);
    this.view.setFloat64(this.length, v, true);
    this.length += 8;
  }

  raw(src: Uint8Array, elementSize: number): void {
    this.reserve(src.length);
    const at = this.length;
    this.bytes.set(src, at);
    if (!LITTLE_ENDIAN && elementSize > 1) swapBytes(this.bytes.subarray(at, at + src.length), elementSize);
    this.length += src.length;
  }

  /** A string reference: index of a string written before, or a new index followed by the string. */
  string(s: string): void {
    const index = this.strings.get(s);
    if (index !== undefined) {
      this.u32(index);
      return;
    }
    const n = this.strings.size;
    this.strings.set(s, n);
    this.u32(n);
    const utf8 = this.encoder.encode(s);
    this.u32(utf8.length);
    this.raw(utf8, 1);
  }

  /** Element type, element count, then the little-endian bytes up to the last non-zero one. */
  typed(value: AnyTypedArray, code: number): void {
    let bytes = new Uint8Array(value.buffer, value.byteOffset, value.byteLength);
    if (!LITTLE_ENDIAN && value.BYTES_PER_ELEMENT > 1) {
      bytes = bytes.slice();
      swapBytes(bytes, value.BYTES_PER_ELEMENT);
    }
    let stored = bytes.length;
    while (stored > 0 && bytes[stored - 1] === 0) stored--;
    this.u8(code);
    this.u32(value.length);
    this.u32(stored);
    this.raw(bytes.subarray(0, stored), 1);
  }

  /** A copy of the bytes written so far. */
  result(): Uint8Array {
    return this.bytes.slice(0, this.length);
  }
}

/** Thrown by ByteReader on malformed input; turned into a FulcrumError by the caller. */
export class CorruptSnapshot extends Error {}

/** Reads what ByteWriter wrote; every read is bounds-checked. */
export class ByteReader {
  private readonly view: DataView;
  pos: number;
  private readonly strings: string[] = [];
  private readonly decoder = new TextDecoder('utf-8', { fatal: true });

  constructor(
    private readonly bytes: Uint8Array,
    start: number,
    private readonly end: number,
  ) {
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.pos = start;
  }

  get done(): boolean {
    return this.pos === this.end;
  }

  get remaining(): number {
    return this.end - this.pos;
  }

  private need(n: number): number {
    const at = this.pos;
    if (n < 0 || at + n > this.end) throw new CorruptSnapshot('truncated data');
    this.pos = at + n;
    return at;
  }

  u8(): number {
    return this.view.getUint8(this.need(1));
  }

  u16(): number {
    return this.view.getUint16(this.need(2), true);
  }

  u32(): number {
    return this.view.getUint32(this.need(4), true);
  }

  i32(): number {
    return this.view.getInt32(this.need(4), true);
  }

  f64(): number {
    return this.view.getFloat64(this.need(8), true);
  }

  string(): string {
    const index = this.u32();
    if (index < this.strings.length) return this.strings[index];
    if (index !== this.strings.length) throw new CorruptSnapshot(`bad string reference ${index}`);
    const n = this.u32();
    const at = this.need(n);
    let s: string;
    try {
      s = this.decoder.decode(this.bytes.subarray(at, at + n));
    } catch {
      throw new CorruptSnapshot('bad UTF-8 string');
    }
    this.strings.push(s);
    return s;
  }

  typed(): AnyTypedArray {
    const code = this.u8();
    const Ctor = TYPED_ARRAY_TYPES[code];
    if (Ctor === undefined) throw new CorruptSnapshot(`bad typed array type ${code}`);
    const length = this.u32();
    const size = Ctor.BYTES_PER_ELEMENT;
    const stored = this.u32();
    if (stored > length * size) throw new CorruptSnapshot('bad typed array');
    const at = this.need(stored);
    const value = new Ctor(length);
    const target = new Uint8Array(value.buffer);
    target.set(this.bytes.subarray(at, at + stored));
    if (!LITTLE_ENDIAN && size > 1) swapBytes(target, size);
    return value;
  }
}

/** 32-bit FNV-1a over bytes. */
export function fnv1a(bytes: Uint8Array, start = 0, end = bytes.length): number {
  let h = 0x811c9dc5;
  for (let i = start; i < end; i++) {
    h ^= bytes[i];
    h = Math.imul(h, 0x01000193);
  }
  return h >>> 0;
}
