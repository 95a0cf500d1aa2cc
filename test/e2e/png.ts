/** A small PNG decoder for screenshots: 8-bit greyscale, RGB or RGBA, not interlaced. */
import { inflateSync } from 'node:zlib';

export interface Image {
  width: number;
  height: number;
  /** RGBA, 4 bytes per pixel, row by row */
  data: Uint8Array;
}

function paeth(a: number, b: number, c: number): number {
  const p = a + b - c;
  const pa = Math.abs(p - a);
  const pb = Math.abs(p - b);
  const pc = Math.abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

export function decodePng(png: Uint8Array): Image {
  const buf = Buffer.from(png.buffer, png.byteOffset, png.byteLength);
  if (buf.readUInt32BE(0) !== 0x89504e47) throw new Error('not a PNG');
  let offset = 8;
  let width = 0;
  let height = 0;
  let colorType = 0;
  const chunks: Buffer[] = [];
  while (offset < buf.length) {
    const length = buf.readUInt32BE(offset);
    const type = buf.toString('ascii', offset + 4, offset + 8);
    const body = buf.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      const depth = body[8];
      colorType = body[9];
      if (depth !== 8 || body[12] !== 0)
        throw new Error(`unsupported PNG: depth ${depth}, interlace ${body[12]}`);
    } else if (type === 'IDAT') {
      chunks.push(body);
    } else if (type === 'IEND') {
      break;
    }
    offset += 12 + length;
  }
  const channels = colorType === 6 ? 4 : colorType === 2 ? 3 : colorType === 0 ? 1 : 0;
  if (channels === 0) throw new Error(`unsupported PNG colour type ${colorType}`);
  const raw = inflateSync(Buffer.concat(chunks));
  const stride = width * channels;
  const pixels = new Uint8Array(stride * height);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const src = y * (stride + 1) + 1;
    const dst = y * stride;
    for (let x = 0; x < stride; x++) {
      const value = raw[src + x];
      const a = x >= channels ? pixels[dst + x - channels] : 0;
      const b = y > 0 ? pixels[dst - stride + x] : 0;
      const c = x >= channels && y > 0 ? pixels[dst - stride + x - channels] : 0;
      let out: number;
      switch (filter) {
        case 0:
          out = value;
          break;
        case 1:
          out = value + a;
          break;
        case 2:
          out = value + b;
          break;
        case 3:
          out = value + ((a + b) >> 1);
          break;
        case 4:
          out = value + paeth(a, b, c);
          break;
        default:
          throw new Error(`bad PNG filter ${filter}`);
      }
      pixels[dst + x] = out & 255;
    }
  }
  const data = new Uint8Array(width * height * 4);
  for (let i = 0; i < width * height; i++) {
    if (channels === 1) {
      data[i * 4] = data[i * 4 + 1] = data[i * 4 + 2] = pixels[i];
      data[i * 4 + 3] = 255;
    } else {
      data[i * 4] = pixels[i * channels];
      data[i * 4 + 1] = pixels[i * channels + 1];
      data[i * 4 + 2] = pixels[i * channels + 2];
      data[i * 4 + 3] = channels === 4 ? pixels[i * channels + 3] : 255;
    }
  }
  return { width, height, data };
}

/** Share of pixels that differ from the most common colour (the background), and the colour count. */
export function inkStats(image: Image): { ink: number; colors: number } {
  const counts = new Map<number, number>();
  const n = image.width * image.height;
  const d = image.data;
  for (let i = 0; i < n; i++) {
    const key = (d[i * 4] << 16) | (d[i * 4 + 1] << 8) | d[i * 4 + 2];
    counts.set(key, (counts.get(key) ?? 0) + 1);
  }
  let background = 0;
  for (const c of counts.values()) background = Math.max(background, c);
  return { ink: 1 - background / n, colors: counts.size };
}

/** Share of pixels whose colour differs by more than `threshold` in any channel. */
export function differingShare(a: Image, b: Image, threshold = 8): number {
  if (a.width !== b.width || a.height !== b.height) return 1;
  const n = a.width * a.height;
  let differ = 0;
  for (let i = 0; i < n; i++) {
    const k = i * 4;
    if (
      Math.abs(a.data[k] - b.data[k]) > threshold ||
      Math.abs(a.data[k + 1] - b.data[k + 1]) > threshold ||
      Math.abs(a.data[k + 2] - b.data[k + 2]) > threshold
    ) {
      differ++;
    }
  }
  return differ / n;
}
