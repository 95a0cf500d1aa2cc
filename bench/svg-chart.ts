/** An SVG bar chart of ms per step: one group per scene, one bar per engine, scaled per scene. */
import type { EngineInfo } from './report';
import { formatMs, type RunResult } from './result';

const COLORS = ['#e4572e', '#1f77b4', '#76b7e5', '#2ca02c', '#9467bd', '#8c564b', '#bcbd22', '#7f7f7f'];
const BAR = 14;
const GAP = 4;
const LABEL_WIDTH = 150;
const BAR_WIDTH = 520;
const WIDTH = LABEL_WIDTH + BAR_WIDTH + 110;

const escapeXml = (s: string) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

export function svgChart(
  engines: EngineInfo[],
  scenes: string[],
  results: RunResult[],
  title: string,
): string {
  const parts: string[] = [];
  let y = 40;
  parts.push(`<text x="10" y="22" font-size="15" font-weight="bold">${escapeXml(title)}</text>`);
  for (const scene of scenes) {
    const rows = engines.map((e) => ({
      engine: e,
      r: results.find((r) => r.engine === e.id && r.scene === scene),
    }));
    const max = Math.max(0, ...rows.map(({ r }) => r?.msPerStep?.median ?? 0));
    parts.push(`<text x="10" y="${y + 12}" font-size="13" font-weight="bold">${escapeXml(scene)}</text>`);
    y += 18;
    rows.forEach(({ engine, r }, i) => {
      const color = COLORS[i % COLORS.length];
      parts.push(
        `<text x="${LABEL_WIDTH - 6}" y="${y + BAR - 3}" font-size="11" text-anchor="end">${escapeXml(engine.label)}</text>`,
      );
      const ms = r?.msPerStep?.median;
      if (ms !== undefined && max > 0) {
        const w = Math.max(1, (ms / max) * BAR_WIDTH);
        parts.push(
          `<rect x="${LABEL_WIDTH}" y="${y}" width="${w.toFixed(1)}" height="${BAR}" fill="${color}"/>`,
        );
        parts.push(
          `<text x="${(LABEL_WIDTH + w + 4).toFixed(1)}" y="${y + BAR - 3}" font-size="11">${formatMs(ms)} ms</text>`,
        );
      } else {
        parts.push(`<text x="${LABEL_WIDTH + 4}" y="${y + BAR - 3}" font-size="11" fill="#888">n/a</text>`);
      }
      y += BAR + GAP;
    });
    y += 10;
  }
  parts.push(
    `<text x="10" y="${y + 6}" font-size="11" fill="#555">ms per step, median; bars scaled per scene; shorter is faster</text>`,
  );
  const height = y + 16;
  return [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${WIDTH}" height="${height}" viewBox="0 0 ${WIDTH} ${height}" font-family="sans-serif">`,
    `<rect width="${WIDTH}" height="${height}" fill="#fff"/>`,
    ...parts,
    '</svg>',
    '',
  ].join('\n');
}
