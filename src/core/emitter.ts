/**
 * A small typed event emitter: `on` returns the function that unsubscribes. The world's events
 * (api/events.ts) and the render layer's runner, renderer and pointer share it.
 */
export class Emitter<Events extends object> {
  private readonly handlers = new Map<keyof Events, ((e: never) => void)[]>();

  on<K extends keyof Events>(event: K, handler: (e: Events[K]) => void): () => void {
    let list = this.handlers.get(event);
    if (!list) {
      list = [];
      this.handlers.set(event, list);
    }
    list.push(handler as (e: never) => void);
    return () => this.off(event, handler);
  }

  off<K extends keyof Events>(event: K, handler: (e: Events[K]) => void): void {
    const list = this.handlers.get(event);
    if (!list) return;
    const i = list.indexOf(handler as (e: never) => void);
    if (i >= 0) list.splice(i, 1);
  }

  /** Calls the handlers in the order they subscribed (a copy, so handlers may unsubscribe). */
  emit<K extends keyof Events>(event: K, e: Events[K]): void {
    const list = this.handlers.get(event);
    if (!list || list.length === 0) return;
    for (const handler of list.slice()) (handler as (e: Events[K]) => void)(e);
  }

  /**
   * emit for each of `items` in order; the handlers are those subscribed when it starts (one that
   * unsubscribes during the delivery still gets the rest).
   */
  emitEach<K extends keyof Events>(event: K, items: readonly Events[K][]): void {
    const list = this.handlers.get(event);
    if (!list || list.length === 0 || items.length === 0) return;
    const handlers = list.slice();
    for (const item of items) for (const handler of handlers) (handler as (e: Events[K]) => void)(item);
  }

  has(event: keyof Events): boolean {
    return (this.handlers.get(event)?.length ?? 0) > 0;
  }

  clear(): void {
    this.handlers.clear();
  }
}
