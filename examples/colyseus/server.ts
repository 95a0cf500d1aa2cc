/**
 * A Colyseus server of Fulcrum physics rooms: `npm run demo:colyseus -- [port=2567]`, then open the
 * gallery's Colyseus page (`npm start`, "Physics rooms over Colyseus"), in several tabs to share a room.
 * One process here; Colyseus spreads rooms over several with its Redis presence and driver
 * (@colyseus/redis-presence, @colyseus/redis-driver) and a load balancer, with no change to the room.
 */
import { Server } from '@colyseus/core';
import { WebSocketTransport } from '@colyseus/ws-transport';
import { PhysicsRoom } from './physics-room';

/** A server with the `physics` room defined, listening on `port` (0: any free one); answers its port. */
export async function startPhysicsServer(
  port: number,
  host = '0.0.0.0',
): Promise<{ server: Server; port: number }> {
  const transport = new WebSocketTransport();
  const server = new Server({ transport, greet: false });
  server.define('physics', PhysicsRoom);
  await server.listen(port, host);
  const address = (transport.server?.address() ?? null) as { port: number } | null;
  return { server, port: address?.port ?? port };
}

const isMain = import.meta.url === `file://${process.argv[1]}`;
if (isMain) {
  const requested = Number(process.argv[2] ?? 2567);
  const { port } = await startPhysicsServer(requested);
  console.log(`Fulcrum physics rooms on ws://localhost:${port} (room name "physics"); Ctrl+C stops`);
}
