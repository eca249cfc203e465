// Union-find over a tick's packed candidates, for the rules that move or hold groups of balls together
// (src/contacts/fixedJam.ts, fixedShock.ts). A join hangs the higher root under the lower, so a group's
// root is its lowest candidate whatever the order of the joins; lookups halve the path as they go.

/** The root of candidate i's group. */
export function rootOf(parent: Int32Array, i: number): number {
  while (parent[i] !== i) {
    const g = parent[parent[i]!]!
    parent[i] = g
    i = g
  }
  return i
}

/** Joins the groups of candidates a and b; whether they were apart. */
export function unite(parent: Int32Array, a: number, b: number): boolean {
  const ra = rootOf(parent, a)
  const rb = rootOf(parent, b)
  if (ra === rb) return false
  if (ra < rb) parent[rb] = ra
  else parent[ra] = rb
  return true
}
