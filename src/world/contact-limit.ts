import { type BroadPhase, type PairAdmission, ProxyType, SearchMode } from '../broad-phase/broad-phase';
import { IntList } from '../broad-phase/int-list';
import { growF64, growI32, growU8 } from '../core/grow';
import type { Settings } from '../core/settings';
import type { BodyStore } from '../store/body-store';
import { BodyFlag, BodyKind } from '../store/body-store';
import { ContactFlag, type ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';

/**
 * What the limiter reads and does in its world (WorldCore implements it): named here so that the
 * limiter does not depend on the module of the world that owns it.
 */
interface LimiterWorld {
  readonly shapes: ShapeStore;
  readonly bodies: BodyStore;
  readonly contacts: ContactStore;
  readonly settings: Settings;
  destroyContact(c: number, events: boolean): void;
}

/** The default of `world.maxContactsPerShape`. An enum for the reason in store/body-store.ts. */
enum ContactLimit {
  /**
   * Above what shapes that do not overlap need: the most contacts counted against one shape over
   * the benchmark and test scenes is 24 (10 cm grains poured in a box), 19 in the tumbler. Finer
   * grains have more (the broad phase's margin is 10 cm whatever their size), most of them with
   * shapes centimetres away, and keep the nearest. A crowd of n equal shapes holds at most 16 n.
   */
  DEFAULT = 32,
}

/** Steps without a crowd after which a new one is warned of. An enum for the reason in body-store.ts. */
export enum WarningRearm {
  STEPS = 60,
}

/** A shape's state in the limiter (ContactLimiter.state). */
enum Wait {
  /** the shape is in `waiting` */
  LISTED = 1,
  /** some of its pairs were left out for want of room (its own or its partner's) */
  WAITING = 2,
  /** some of those overlap it (their boxes do): it passes through shapes for want of room */
  OVERLAPPED = 4,
  /** at its limit with no contact to give up (none has its boxes apart), as of this step's search */
  SEALED = 8,
  /** buffered by `requeue` alone (its proxy did not move) */
  REQUEUED = 16,
}

/**
 * The contact limit: bounds the contacts, and so the memory and the work of a step, of shapes heaped
 * on each other (thousands of bodies created on one spot overlap pairwise: n^2 / 2 contacts).
 *
 * A contact counts against the smaller of its two shapes by centroidExtent (against both when they
 * are the same size), except that a dynamic shape's contacts with static and kinematic shapes count
 * only against those: the ground a crowd stands on is never refused, and a large shape (a plank, a
 * drum) carries any number of smaller ones. Every contact counts against at least one shape, or
 * involves a static or kinematic shape larger than its dynamic one, so a crowd's contacts grow as
 * limit x shapes, not as shapes^2.
 *
 * The broad phase hands each shape's new candidate pairs to `admit`: when they all fit they are all
 * kept (so a scene under the limit runs exactly as without it). Otherwise each shape keeps the
 * pairs nearest to it, by the gap between the two shapes' boxes (deepest overlap first, then the
 * lower partner id): a shape at its limit gives up its farthest contact whose boxes are apart (it
 * holds at most a speculative point) for a nearer pair. Shapes left with pairs out wait in `waiting`
 * and search again at every step in which they have room or a contact to give up, so that shapes
 * coming closer get their contact in time.
 * @internal
 */
export class ContactLimiter implements PairAdmission {
  /** contacts that may count against one shape (world.maxContactsPerShape) */
  limit: number = ContactLimit.DEFAULT;
  /** shapes with Wait.LISTED, in the order they were first left with pairs out */
  readonly waiting = new IntList();
  /**
   * steps since shapes last passed through others for want of room, and since proxies last waited
   * for the pair search, up to WarningRearm.STEPS (see warnOfCrowds in narrow-phase.ts)
   */
  quietLimit: number = WarningRearm.STEPS;
  quietSearch: number = WarningRearm.STEPS;
  /** per shape slot: pairs admitted in the current search, not yet contacts */
  private pending = new Int32Array(0);
  /** per shape slot: Wait flags */
  private state = new Uint8Array(0);
  /** the current search's shape at its limit: pairs not looked up, and those whose boxes overlap */
  private blocked = 0;
  private blockedOverlapping = 0;
  /**
   * the nearest pairs of a shape over its room: a max-heap by (gap, partner shape id) of candidates
   * (ref >= 0: the partner) and of contacts it may give up (ref < 0: ~ their index in yieldContact)
   */
  private heapGap = new Float64Array(0);
  private heapPartner = new Int32Array(0);
  private heapRef = new Int32Array(0);
  /** the current shape's contacts it may give up, their gap and partner, and whether kept */
  private yieldContact = new Int32Array(0);
  private yieldGap = new Float64Array(0);
  private yieldPartner = new Int32Array(0);
  private yieldKept = new Uint8Array(0);
  /**
   * at most the size of the smallest dynamic shape: the smallest made dynamic so far (not raised when
   * it goes: a smaller bound only makes begin close fewer searches)
   */
  private minDynamicExtent = Number.POSITIVE_INFINITY;
  /** whether the current search was closed (see begin) */
  private closed = false;
  /** how far the current narrowed search reaches, 0 when it is not narrowed (see searchBox) */
  private nearReach = 0;
  /** what farthestApart found */
  private apartGap = 0;
  private apartPartner = 0;

  constructor(private readonly core: LimiterWorld) {}

  get anyWaiting(): boolean {
    return this.waiting.length > 0;
  }

  /** Whether a contact between shapes a and b counts against a. */
  counts(a: number, b: number): boolean {
    const shapes = this.core.shapes;
    if (shapes.centroidExtent[a] > shapes.centroidExtent[b]) return false;
    return (shapes.proxyKey[a] & 3) !== ProxyType.DYNAMIC || (shapes.proxyKey[b] & 3) === ProxyType.DYNAMIC;
  }

  /** Counts a new contact against its shapes, and marks which ones on the contact. */
  charge(contacts: ContactStore, c: number): void {
    const a = contacts.shapeA[c];
    const b = contacts.shapeB[c];
    const load = this.core.shapes.contactLoad;
    let flags = 0;
    if (this.counts(a, b)) {
      load[a]++;
      flags |= ContactFlag.COUNTS_A;
    }
    if (this.counts(b, a)) {
      load[b]++;
      flags |= ContactFlag.COUNTS_B;
    }
    contacts.flags[c] |= flags;
  }

  /** Takes a contact about to be destroyed off its shapes' counts. */
  discharge(contacts: ContactStore, c: number): void {
    const flags = contacts.flags[c];
    const load = this.core.shapes.contactLoad;
    if ((flags & ContactFlag.COUNTS_A) !== 0) load[contacts.shapeA[c]]--;
    if ((flags & ContactFlag.COUNTS_B) !== 0) load[contacts.shapeB[c]]--;
  }

  /**
   * Before a search: sizes the per-shape scratch, drops the shapes that wait no more from `waiting`,
   * and buffers those that have room or a contact to give up, so that the search looks for their
   * pairs (but not those of sleeping bodies); the others are sealed for this search.
   */
  requeue(broad: BroadPhase): void {
    const shapes = this.core.shapes;
    const bodies = this.core.bodies;
    if (this.pending.length < shapes.capacity) {
      this.pending = growI32(this.pending, shapes.capacity);
      this.state = growU8(this.state, shapes.capacity);
    }
    const state = this.state;
    const list = this.waiting;
    const data = list.data;
    let kept = 0;
    for (let i = 0; i < list.length; i++) {
      const s = data[i];
      // (a shape destroyed since is dropped; one made in its slot since is searched once)
      if (shapes.alive[s] === 0 || (state[s] & Wait.WAITING) === 0) {
        state[s] = 0;
        continue;
      }
      data[kept++] = s;
      // a sleeping body waits where it is: a body that wakes it searches, and finds it
      const body = shapes.body[s];
      if (bodies.kind[body] !== BodyKind.STATIC && (bodies.flags[body] & BodyFlag.AWAKE) === 0) {
        state[s] &= ~Wait.SEALED;
        continue;
      }
      if (this.isSealed(s)) state[s] |= Wait.SEALED;
      else {
        state[s] &= ~Wait.SEALED;
        const key = shapes.proxyKey[s];
        if (!broad.isBuffered(key)) {
          state[s] |= Wait.REQUEUED;
          broad.bufferMove(key);
        }
      }
    }
    list.length = kept;
  }

  /**
   * Starts the search of shape s. When s is sealed the search hands the pairs that would count
   * against s to `block` instead of looking them up (in a crowd of n shapes on one spot, most of the
   * n a search finds); when no dynamic shape is smaller than s, none can pair with it, and the
   * search leaves the dynamic tree and s's waiting state alone.
   */
  begin(s: number): SearchMode {
    this.blocked = 0;
    this.blockedOverlapping = 0;
    this.closed = false;
    if (!this.isSealed(s)) return SearchMode.OPEN;
    if (this.core.shapes.centroidExtent[s] > this.minDynamicExtent) return SearchMode.SEALED;
    this.closed = true;
    return SearchMode.CLOSED;
  }

  /** Notes a new dynamic shape's size (see minDynamicExtent). */
  noteDynamic(extent: number): void {
    this.minDynamicExtent = Math.min(this.minDynamicExtent, extent);
  }

  /** A shape j that overlaps s, may pair with it and would count against sealed s. */
  block(s: number, j: number): void {
    this.blocked++;
    if (this.gap(s, j) <= 0) this.blockedOverlapping++;
  }

  /**
   * Whether a pair of s with j is refused before it is looked up: j is sealed and waits already (so
   * the pair, contact or not, changes nothing now), and the pair would count against it.
   */
  refuses(s: number, j: number): boolean {
    return (
      (this.state[j] & (Wait.WAITING | Wait.SEALED)) === (Wait.WAITING | Wait.SEALED) && this.counts(j, s)
    );
  }

  /**
   * A shape searching again only because it waits (its proxy did not move) found every pair of its
   * fat box before, and left out the farther ones: at its limit, it looks only as far as its
   * farthest contact whose boxes are apart, and no further than half the fat boxes' margin (the tree
   * holds fat boxes, so it finds those a margin further: isNear drops them at once). Shapes
   * approaching each other more slowly than that a step are found before they touch; faster ones
   * leave their fat boxes and search them. (A 2 cm grain in a pile finds 130 boxes in its fat box;
   * each of its 32 nearest is up to 8 cm away.)
   */
  searchBox(s: number, box: Float64Array): boolean {
    const state = this.state[s];
    this.nearReach = 0;
    if ((state & Wait.REQUEUED) === 0) return false;
    this.state[s] = state & ~Wait.REQUEUED;
    const shapes = this.core.shapes;
    if (shapes.contactLoad[s] + this.pending[s] < this.limit) return false;
    const c = this.farthestApart(s);
    if (c === -1) return false;
    const reach = Math.min(this.apartGap, 0.5 * this.core.settings.aabbMargin);
    this.nearReach = reach;
    box[0] = shapes.minX[s] - reach;
    box[1] = shapes.minY[s] - reach;
    box[2] = shapes.maxX[s] + reach;
    box[3] = shapes.maxY[s] + reach;
    return true;
  }

  /** Whether the tight boxes of s and j are at most the narrowed search's reach apart. */
  isNear(s: number, j: number): boolean {
    return this.gap(s, j) <= this.nearReach;
  }

  /**
   * Keeps, of the candidate pairs `out[from, out.length)` that shape `s`'s search found (each pair
   * once, the two ids in either order), those the limit allows, and counts them as pending. Then
   * notes whether s waits: some pairs were left out for want of its room. (Sealed s found more
   * blocked shapes than it has contacts and pending pairs: some of them have no contact with it; its
   * contacts all overlap it, so more overlapping ones than that tell that some of those have none.)
   */
  admit(s: number, out: IntList, from: number): void {
    const taken = this.core.shapes.contactLoad[s] + this.pending[s];
    // a narrowed search did not see the pairs left out further away: s waits for them still
    let waits = this.blocked > taken || this.nearReach > 0;
    let overlapped = this.blockedOverlapping > taken;
    this.nearReach = 0;
    if (out.length > from) {
      if (this.fits(s, out, from)) this.admitAll(s, out, from);
      else {
        const left = this.admitNearest(s, out, from);
        waits ||= left > 0;
        overlapped ||= left > 1;
      }
    }
    // (a closed search did not look at the dynamic shapes: s's state stands)
    if (this.closed) return;
    const state = this.state[s];
    if (!waits) {
      this.state[s] = state & Wait.LISTED;
      return;
    }
    this.state[s] = (state & (Wait.LISTED | Wait.SEALED)) | Wait.WAITING | (overlapped ? Wait.OVERLAPPED : 0);
    if ((state & Wait.LISTED) === 0) this.list(s);
  }

  /** After the contacts of a search were made: clears the pending counts of the pairs' shapes. */
  settle(pairs: IntList): void {
    const pending = this.pending;
    const data = pairs.data;
    for (let i = 0; i < pairs.length; i++) pending[data[i]] = 0;
  }

  /** Shapes that pass through shapes they overlap for want of room (destroyed ones not counted). */
  get crowdedCount(): number {
    let n = 0;
    for (let i = 0; i < this.waiting.length; i++) if (this.isCrowded(this.waiting.data[i])) n++;
    return n;
  }

  /** The first crowded shape (see crowdedCount), or -1. */
  firstCrowded(): number {
    for (let i = 0; i < this.waiting.length; i++) {
      const s = this.waiting.data[i];
      if (this.isCrowded(s)) return s;
    }
    return -1;
  }

  private isCrowded(s: number): boolean {
    return this.core.shapes.alive[s] !== 0 && (this.state[s] & Wait.OVERLAPPED) !== 0;
  }

  /** Whether s is at its limit with no contact to give up. */
  private isSealed(s: number): boolean {
    return this.core.shapes.contactLoad[s] + this.pending[s] >= this.limit && this.listYielding(s) === 0;
  }

  /** The gap between the tight boxes of shapes a and b, negative when they overlap. */
  private gap(a: number, b: number): number {
    const shapes = this.core.shapes;
    return Math.max(
      shapes.minX[a] - shapes.maxX[b],
      shapes.minX[b] - shapes.maxX[a],
      shapes.minY[a] - shapes.maxY[b],
      shapes.minY[b] - shapes.maxY[a],
    );
  }

  /** Whether every candidate pair fits in the room of its shapes. */
  private fits(s: number, out: IntList, from: number): boolean {
    const load = this.core.shapes.contactLoad;
    const pending = this.pending;
    const limit = this.limit;
    const data = out.data;
    let needed = 0;
    for (let r = from; r < out.length; r += 2) {
      const j = data[r] === s ? data[r + 1] : data[r];
      if (this.counts(s, j)) needed++;
      if (this.counts(j, s) && load[j] + pending[j] >= limit) return false;
    }
    return needed === 0 || load[s] + pending[s] + needed <= limit;
  }

  private admitAll(s: number, out: IntList, from: number): void {
    const pending = this.pending;
    const data = out.data;
    for (let r = from; r < out.length; r += 2) {
      const j = data[r] === s ? data[r + 1] : data[r];
      if (this.counts(s, j)) pending[s]++;
      if (this.counts(j, s)) pending[j]++;
    }
  }

  /**
   * admit's way when not every pair fits (see the class comment): compacts `out` to the pairs kept
   * and destroys the contacts given up. Returns 0 when no pair was left out for want of s's room, 1
   * when some were, 2 when some of those overlap s.
   */
  private admitNearest(s: number, out: IntList, from: number): number {
    const pending = this.pending;
    const yielding = this.listYielding(s);
    const room = Math.max(0, this.limit - this.core.shapes.contactLoad[s] - pending[s]);
    const capacity = room + yielding;
    if (this.heapGap.length < capacity) {
      this.heapGap = growF64(this.heapGap, 2 * capacity);
      this.heapPartner = growI32(this.heapPartner, 2 * capacity);
      this.heapRef = growI32(this.heapRef, 2 * capacity);
    }
    let size = 0;
    for (let k = 0; k < yielding; k++) this.push(size++, this.yieldGap[k], this.yieldPartner[k], ~k);
    const data = out.data;
    const end = out.length;
    let write = from;
    let left = 0;
    for (let r = from; r < end; r += 2) {
      const a = data[r];
      const b = data[r + 1];
      const j = a === s ? b : a;
      const gap = this.gap(s, j);
      if (!this.counts(s, j)) {
        if (this.takeRoom(j, gap, s)) {
          data[write++] = a;
          data[write++] = b;
        }
        continue;
      }
      // compete for s's room with the other candidates and the contacts it may give up
      let outGap = gap;
      let outRef = j;
      if (size < capacity) {
        this.push(size++, gap, j, j);
        outRef = -1;
      } else if (size > 0 && !after(gap, j, this.heapGap[0], this.heapPartner[0])) {
        outGap = this.heapGap[0];
        outRef = this.heapRef[0];
        this.replaceTop(size, gap, j, j);
      }
      if (outRef >= 0) left = Math.max(left, outGap <= 0 ? 2 : 1);
    }
    // the nearest candidates take s's room, then the places of the farthest contacts it gives up
    const kept = this.yieldKept;
    kept.fill(0, 0, yielding);
    let admitted = 0;
    for (let k = 0; k < size; k++) {
      const j = this.heapRef[k];
      if (j < 0) {
        kept[~j] = 1;
        continue;
      }
      // (refused for j's room, the pair waits for j: j searches again, and s need not)
      if (!this.takeRoom(j, this.heapGap[k], s)) continue;
      pending[s]++;
      admitted++;
      data[write++] = Math.min(s, j);
      data[write++] = Math.max(s, j);
    }
    out.length = write;
    for (let given = room; given < admitted; given++) this.destroy(this.farthestYielding(yielding));
    return left;
  }

  /**
   * Makes room for a pair of j with `partner`, `gap` apart, if it counts against j: there is room
   * already, or j gives up its farthest contact whose boxes are apart if that is farther. Counts the
   * pair as pending; returns false, and marks j waiting, when there is no room.
   */
  private takeRoom(j: number, gap: number, partner: number): boolean {
    if (!this.counts(j, partner)) return true;
    if (this.core.shapes.contactLoad[j] + this.pending[j] < this.limit) {
      this.pending[j]++;
      return true;
    }
    const c = this.farthestApart(j);
    if (c !== -1 && after(this.apartGap, this.apartPartner, gap, partner)) {
      this.core.destroyContact(c, true);
      this.pending[j]++;
      return true;
    }
    const state = this.state[j];
    this.state[j] = state | Wait.WAITING | (gap <= 0 ? Wait.OVERLAPPED : 0) | (c === -1 ? Wait.SEALED : 0);
    if ((state & Wait.LISTED) === 0) this.list(j);
    return false;
  }

  /**
   * The farthest contact that counts against j and whose boxes are apart, or -1; its gap and partner
   * in apartGap and apartPartner. (Not listYielding: that holds the searching shape's.)
   */
  private farthestApart(j: number): number {
    const core = this.core;
    const contacts = core.contacts;
    let best = -1;
    for (let e = core.bodies.contactHead[core.shapes.body[j]]; e !== -1; e = contacts.edgeNext[e]) {
      const c = e >> 1;
      const side = e & 1;
      if ((side === 0 ? contacts.shapeA[c] : contacts.shapeB[c]) !== j) continue;
      if ((contacts.flags[c] & (side === 0 ? ContactFlag.COUNTS_A : ContactFlag.COUNTS_B)) === 0) continue;
      const partner = side === 0 ? contacts.shapeB[c] : contacts.shapeA[c];
      const gap = this.gap(j, partner);
      if (gap <= 0 || (best !== -1 && !after(gap, partner, this.apartGap, this.apartPartner))) continue;
      best = c;
      this.apartGap = gap;
      this.apartPartner = partner;
    }
    return best;
  }

  /**
   * Lists in yieldContact (with gap and partner) the contacts that count against s and whose boxes
   * are apart (they hold at most a speculative point); returns how many.
   */
  private listYielding(s: number): number {
    const core = this.core;
    const contacts = core.contacts;
    const shapes = core.shapes;
    let n = 0;
    for (let e = core.bodies.contactHead[shapes.body[s]]; e !== -1; e = contacts.edgeNext[e]) {
      const c = e >> 1;
      const side = e & 1;
      if ((side === 0 ? contacts.shapeA[c] : contacts.shapeB[c]) !== s) continue;
      if ((contacts.flags[c] & (side === 0 ? ContactFlag.COUNTS_A : ContactFlag.COUNTS_B)) === 0) continue;
      const j = side === 0 ? contacts.shapeB[c] : contacts.shapeA[c];
      const gap = this.gap(s, j);
      if (gap <= 0) continue;
      if (n === this.yieldContact.length) {
        const capacity = Math.max(16, 2 * n);
        this.yieldContact = growI32(this.yieldContact, capacity);
        this.yieldGap = growF64(this.yieldGap, capacity);
        this.yieldPartner = growI32(this.yieldPartner, capacity);
        this.yieldKept = growU8(this.yieldKept, capacity);
      }
      this.yieldContact[n] = c;
      this.yieldGap[n] = gap;
      this.yieldPartner[n] = j;
      n++;
    }
    return n;
  }

  /** The index in yieldContact of the farthest contact not kept (yieldKept) and not destroyed yet. */
  private farthestYielding(count: number): number {
    let best = -1;
    for (let k = 0; k < count; k++) {
      if (this.yieldKept[k] !== 0) continue;
      if (
        best === -1 ||
        after(this.yieldGap[k], this.yieldPartner[k], this.yieldGap[best], this.yieldPartner[best])
      )
        best = k;
    }
    return best;
  }

  /** Destroys the contact at index k of yieldContact, and marks it so. */
  private destroy(k: number): void {
    this.yieldKept[k] = 1;
    this.core.destroyContact(this.yieldContact[k], true);
  }

  private list(s: number): void {
    this.state[s] |= Wait.LISTED;
    this.waiting.push(s);
  }

  /** Adds (gap, partner, ref) at index `at` of the heap of `at` entries. */
  private push(at: number, gap: number, partner: number, ref: number): void {
    const heapGap = this.heapGap;
    const heapPartner = this.heapPartner;
    const heapRef = this.heapRef;
    let i = at;
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (!after(gap, partner, heapGap[parent], heapPartner[parent])) break;
      heapGap[i] = heapGap[parent];
      heapPartner[i] = heapPartner[parent];
      heapRef[i] = heapRef[parent];
      i = parent;
    }
    heapGap[i] = gap;
    heapPartner[i] = partner;
    heapRef[i] = ref;
  }

  /** Replaces the top (the farthest) of the heap of `size` entries with (gap, partner, ref). */
  private replaceTop(size: number, gap: number, partner: number, ref: number): void {
    const heapGap = this.heapGap;
    const heapPartner = this.heapPartner;
    const heapRef = this.heapRef;
    let i = 0;
    for (;;) {
      const left = 2 * i + 1;
      if (left >= size) break;
      const right = left + 1;
      const child =
        right < size && after(heapGap[right], heapPartner[right], heapGap[left], heapPartner[left])
          ? right
          : left;
      if (!after(heapGap[child], heapPartner[child], gap, partner)) break;
      heapGap[i] = heapGap[child];
      heapPartner[i] = heapPartner[child];
      heapRef[i] = heapRef[child];
      i = child;
    }
    heapGap[i] = gap;
    heapPartner[i] = partner;
    heapRef[i] = ref;
  }
}

/** Whether (gapA, a) orders after (gapB, b): the larger gap, then the larger shape id. */
function after(gapA: number, a: number, gapB: number, b: number): boolean {
  return gapA > gapB || (gapA === gapB && a > b);
}
