/** Terminal tables of a benchmark run: speed, Fulcrum's ratio to each peer, and quality figures. */
import { formatMs, type RunResult } from './result';

export interface EngineInfo {
  id: string;
  label: string;
  version: string;
}

/** the one quality figure that matters for a scene, as text */
export function qualityText(r: RunResult): string {
  const q = r.quality;
  if (!q) return '';
  if (!q.finite) return 'NaN!';
  if (q.maxJointSeparation !== null) return `sep ${(q.maxJointSeparation * 1000).toFixed(1)} mm`;
  if (q.escaped !== null) return `out ${q.escaped}`;
  return `drift ${(q.drift * 1000).toFixed(1)} mm`;
}

function cell(r: RunResult | undefined): string {
  if (!r) return '-';
  if (r.ok && r.msPerStep) return formatMs(r.msPerStep.median);
  return r.stage === 'load' || r.stage === 'free-fall' ? 'n/a' : 'error';
}

function table(header: string[], rows: string[][]): string {
  const widths = header.map((h, i) => Math.max(h.length, ...rows.map((r) => r[i].length)));
  const line = (cells: string[]) =>
    cells.map((c, i) => (i === 0 ? c.padEnd(widths[i]) : c.padStart(widths[i]))).join('  ');
  return [line(header), widths.map((w) => '-'.repeat(w)).join('  '), ...rows.map(line)].join('\n');
}

export function formatReport(
  engines: EngineInfo[],
  scenes: string[],
  results: RunResult[],
  rounds = 1,
  /** where each run starts afresh: a Node process, or a browser page */
  fresh: 'process' | 'page' = 'process',
): string {
  const find = (engine: string, scene: string) =>
    results.find((r) => r.engine === engine && r.scene === scene);
  const out: string[] = [];
  const what =
    rounds > 1
      ? `median of ${rounds} rounds' medians of the timed windows, each round in fresh ${fresh === 'page' ? 'pages' : 'processes'}`
      : 'median of the timed windows';
  out.push(`ms per step (${what}; lower is better)`);
  out.push(
    table(
      ['scene', ...engines.map((e) => e.label)],
      scenes.map((s) => [s, ...engines.map((e) => cell(find(e.id, s)))]),
    ),
  );

  const peers = engines.filter((e) => e.id !== 'fulcrum');
  if (engines.some((e) => e.id === 'fulcrum') && peers.length > 0) {
    const ratio = (scene: string, peer: string): string => {
      const f = find('fulcrum', scene);
      const p = find(peer, scene);
      if (!f?.msPerStep || !p?.msPerStep) return 'n/a';
      const merged = `${(p.msPerStep.median / f.msPerStep.median).toFixed(2)}x`;
      if (!f.roundMedians || !p.roundMedians) return merged;
      // the ratio of each round's medians: how far one round alone could have put it
      const each = p.roundMedians.map((ms, r) => ms / f.roundMedians![r]);
      return `${merged} (${Math.min(...each).toFixed(2)}-${Math.max(...each).toFixed(2)})`;
    };
    out.push('');
    out.push("Fulcrum's speed ratio to each peer (peer ms / Fulcrum ms; above 1 means Fulcrum is faster)");
    if (rounds > 1) out.push('(in brackets: the least and greatest ratio of one round alone)');
    out.push(
      table(
        ['scene', ...peers.map((e) => e.label)],
        scenes.map((s) => [s, ...peers.map((e) => ratio(s, e.id))]),
      ),
    );
  }

  out.push('');
  out.push('quality (drift: largest move of a body since the end of warm-up; sep: largest joint separation;');
  out.push('out: bodies that left the container or tumbler)');
  out.push(
    table(
      ['scene', ...engines.map((e) => e.label)],
      scenes.map((s) => [
        s,
        ...engines.map((e) => qualityText(find(e.id, s) ?? { engine: e.id, scene: s, ok: false })),
      ]),
    ),
  );

  if (results.some((r) => r.coldStart)) {
    const coldCell = (r: RunResult | undefined): string => {
      const c = r?.coldStart;
      if (!c) return '-';
      const settled = c.settledMs === null ? 'never' : `${(c.settledMs / 1000).toFixed(2)} s`;
      return `${formatMs(c.firstStepMs)} / ${formatMs(c.first60Ms)} / ${settled}`;
    };
    out.push('');
    out.push(
      `cold start in a fresh ${fresh} (first step ms / mean of the first 60 steps ms / wall time until`,
    );
    out.push('the steps stay within 10 % of the same steps run warmed)');
    out.push(
      table(
        ['scene', ...engines.map((e) => e.label)],
        scenes.map((s) => [s, ...engines.map((e) => coldCell(find(e.id, s)))]),
      ),
    );
  }

  const failures = results.filter((r) => !r.ok);
  if (failures.length > 0) {
    out.push('');
    out.push('not measured:');
    for (const r of failures) out.push(`  ${r.engine} on ${r.scene}: ${r.stage}: ${r.error}`);
  }
  return out.join('\n');
}
