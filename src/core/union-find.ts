/**
 * Union-find over body slots in an Int32Array of parents (a root is its own parent), shared by the
 * sleep islands and the islands stepped finer. The smaller slot becomes the root, so that the
 * grouping, and every order that follows it, is defined.
 */

/** The root of `b`'s set; compresses the path on the way. */
export function findRoot(parent: Int32Array, b: number): number {
  let root = b;
  while (parent[root] !== root) root = parent[root];
  while (parent[b] !== root) {
    const next = parent[b];
    parent[b] = root;
    b = next;
  }
  return root;
}

/** Joins the sets of `a` and `b`; the smaller root becomes the root of both. */
export function unionRoots(parent: Int32Array, a: number, b: number): void {
  const ra = findRoot(parent, a);
  const rb = findRoot(parent, b);
  if (ra === rb) return;
  if (ra < rb) parent[rb] = ra;
  else parent[ra] = rb;
}
