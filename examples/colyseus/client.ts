/**
 * The gallery's Colyseus client: joins a `physics` room of examples/colyseus/server.ts and draws its
 * world from the state Colyseus keeps in sync, each body eased from its previous pose to the latest
 * over one patch interval. A click drops a ball, sent as a command the room applies at its next step.
 * `?server=ws://host:port` picks the server (default: this page's host, port 2567), `?seed=n` the
 * room's scene; `window.colyseusPage` shows what the page holds, for the e2e test.
 */
import { Client, type Room } from '@colyseus/sdk';
import type { RoomCommand } from '../server/room';
import type { CommandMessage } from './physics-room';
import type { BodyView, PhysicsState } from './state';

const params = new URLSearchParams(location.search);
const secure = location.protocol === 'https:';
const serverUrl =
  params.get('server') ?? `${secure ? 'wss' : 'ws'}://${location.hostname || 'localhost'}:2567`;
const seed = Number(params.get('seed') ?? 1);

/** the scene's view: x across, y up, metres */
const VIEW = { x: 0, y: 8, halfHeight: 12 };
const PATCH_MS = 1000 / 30;

const canvas = document.getElementById('room-canvas') as HTMLCanvasElement;
const ctx = canvas.getContext('2d') as CanvasRenderingContext2D;
const status = document.getElementById('room-status') as HTMLElement;

/** what the page holds: the last state copied out at its arrival, the commands the room accepted */
const page = {
  room: null as Room<PhysicsState> | null,
  last: null as { step: number; poses: number[]; count: number } | null,
  accepted: [] as { step: number; command: RoomCommand }[],
  refused: [] as string[],
};
(window as unknown as { colyseusPage: typeof page }).colyseusPage = page;

/** each body's pose at the previous and at the latest state, and when the latest came */
let previous: number[] = [];
let latest: number[] = [];
let latestAt = 0;
let nextId = 1;
const sent = new Map<number, RoomCommand>();

function setStatus(text: string, state: string): void {
  status.textContent = text;
  status.dataset.state = state;
}

function scale(): number {
  return canvas.height / (2 * VIEW.halfHeight);
}

function toWorld(px: number, py: number): { x: number; y: number } {
  const s = scale();
  return { x: VIEW.x + (px - canvas.width / 2) / s, y: VIEW.y - (py - canvas.height / 2) / s };
}

function drawBody(view: BodyView, x: number, y: number, angle: number, s: number): void {
  const c = Math.cos(angle);
  const sn = Math.sin(angle);
  ctx.save();
  ctx.translate(canvas.width / 2 + (x - VIEW.x) * s, canvas.height / 2 - (y - VIEW.y) * s);
  ctx.scale(s, -s);
  ctx.transform(c, sn, -sn, c, 0, 0);
  ctx.fillStyle = view.isStatic ? '#3a4150' : '#e6a04b';
  ctx.strokeStyle = view.isStatic ? '#596275' : '#f6c68a';
  ctx.lineWidth = 1 / s;
  for (const shape of view.shapes) {
    const p = shape.points;
    ctx.beginPath();
    if (shape.kind === 'circle') {
      ctx.arc(p[0], p[1], shape.radius, 0, 2 * Math.PI);
      ctx.moveTo(p[0], p[1]);
      ctx.lineTo(p[0] + shape.radius, p[1]);
    } else if (shape.kind === 'polygon') {
      ctx.moveTo(p[0], p[1]);
      for (let i = 2; i < p.length; i += 2) ctx.lineTo(p[i], p[i + 1]);
      ctx.closePath();
    } else {
      ctx.moveTo(p[0], p[1]);
      ctx.lineTo(p[2], p[3]);
      ctx.lineWidth = Math.max(2 * shape.radius, 2 / s);
    }
    if (shape.kind === 'circle' || shape.kind === 'polygon') ctx.fill();
    ctx.stroke();
  }
  ctx.restore();
}

function frame(now: number): void {
  const width = Math.round(canvas.clientWidth * devicePixelRatio);
  const height = Math.round(canvas.clientHeight * devicePixelRatio);
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const room = page.room;
  if (room?.state?.bodies) {
    const s = scale();
    const t = Math.min(1, (now - latestAt) / PATCH_MS);
    room.state.bodies.forEach((view, i) => {
      const k = 3 * i;
      if (k + 2 >= latest.length) return;
      const from = k + 2 < previous.length ? previous : latest;
      const x = from[k] + (latest[k] - from[k]) * t;
      const y = from[k + 1] + (latest[k + 1] - from[k + 1]) * t;
      // the shorter way round
      let turn = latest[k + 2] - from[k + 2];
      if (turn > Math.PI) turn -= 2 * Math.PI;
      else if (turn < -Math.PI) turn += 2 * Math.PI;
      drawBody(view, x, y, from[k + 2] + turn * t, s);
    });
  }
  requestAnimationFrame(frame);
}

function dropBall(event: PointerEvent): void {
  const room = page.room;
  if (!room) return;
  const rect = canvas.getBoundingClientRect();
  const at = toWorld(
    (event.clientX - rect.left) * devicePixelRatio,
    (event.clientY - rect.top) * devicePixelRatio,
  );
  const command: RoomCommand = {
    kind: 'spawn',
    body: { type: 'dynamic', position: at, shapes: [{ kind: 'circle', radius: 0.5, density: 2 }] },
  };
  const id = nextId++;
  sent.set(id, command);
  room.send('command', { id, command } satisfies CommandMessage);
}

async function join(how: { roomId?: string; fresh?: boolean } = {}): Promise<void> {
  if (page.room) await page.room.leave();
  page.room = null;
  page.last = null;
  page.accepted = [];
  previous = [];
  latest = [];
  setStatus(`Connecting to ${serverUrl}…`, 'connecting');
  const client = new Client(serverUrl);
  let room: Room<PhysicsState>;
  try {
    // a second tab joins the room the first one made; "New room" and ?seed make one of their own
    if (how.roomId) room = await client.joinById<PhysicsState>(how.roomId);
    else if (how.fresh || params.has('seed')) room = await client.create<PhysicsState>('physics', { seed });
    else room = await client.joinOrCreate<PhysicsState>('physics', { seed });
  } catch (error) {
    setStatus(
      `No Colyseus server at ${serverUrl} (${(error as Error).message || 'refused'}). Start one with npm run demo:colyseus, then reload.`,
      'error',
    );
    return;
  }
  page.room = room;
  room.onStateChange((state) => {
    previous = latest;
    latest = [];
    for (const body of state.bodies) latest.push(body.x, body.y, body.angle);
    latestAt = performance.now();
    page.last = { step: state.step, poses: latest.slice(), count: state.bodies.length };
    setStatus(
      `Room ${room.roomId} on ${serverUrl}: step ${state.step}, ${state.bodies.length} bodies, ${state.stepMs.toFixed(2)} ms a step on the server`,
      'connected',
    );
  });
  room.onMessage('accepted', (m: { id: number; step: number }) => {
    const command = sent.get(m.id);
    if (command) page.accepted.push({ step: m.step, command });
  });
  room.onMessage('refused', (m: { id: number; message: string }) => page.refused.push(m.message));
  room.onLeave(() => {
    if (page.room === room) setStatus('The server closed the room.', 'error');
  });
  history.replaceState(
    null,
    '',
    `?${new URLSearchParams({ ...Object.fromEntries(params), room: room.roomId })}`,
  );
}

canvas.addEventListener('pointerdown', dropBall);
document.getElementById('btn-new-room')?.addEventListener('click', () => {
  params.delete('room');
  void join({ fresh: true });
});
requestAnimationFrame(frame);
void join({ roomId: params.get('room') ?? undefined });
