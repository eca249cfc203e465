// The simulation's components other than Ball (Path, RimContact, Hole, IsHole, Walls) are added by its own
// commands only: each carries rows and lists the simulation keeps in step with it (a hole's row in the hole
// table and grid, the walls' entity, a ball's path and rim slot). Added by a game's addComponent, one made a
// half thing: a Hole on a plain entity read as a hole of radius 0 that captured nothing, on a ball made an
// entity both a ball and a hole. So an addComponent of one of them from outside the simulation is refused:
// the component is taken off again and the call throws, naming what to use instead. A Ball added by hand
// makes a ball out of play (src/world/balls.ts), except on a hole or the walls, which are refused too.
import { addComponent, hasComponent, removeComponent } from 'bitecs'
import type { BallWorld } from './createWorld.js'

/** Depth of the simulation's own adds in progress (JavaScript runs one at a time: one count serves every world). */
let own = 0

/** addComponent for the simulation's own code: the observers let it through. */
export function addOwn(world: BallWorld, eid: number, component: object): void {
  own++
  try {
    addComponent(world, eid, component)
  } finally {
    own--
  }
}

/** onAdd of a component only the simulation adds: refused unless the simulation is adding it (see the top). */
export function refuseForeignAdd(world: BallWorld, eid: number, component: object, name: string, instead: string): void {
  if (own > 0) return
  removeComponent(world, eid, component)
  throw new Error(`addComponent(world, ${eid}, world.${name}): ${name} is added by the simulation only (${instead}); the entity is left as it was`)
}

/** onAdd(Ball): a hole or the walls cannot also be a ball; refused as refuseForeignAdd does. */
export function refuseBallOnFixture(world: BallWorld, eid: number): void {
  const what = hasComponent(world, eid, world.Hole) || hasComponent(world, eid, world.IsHole) ? 'a hole' : hasComponent(world, eid, world.Walls) ? 'the walls' : null
  if (what === null) return
  removeComponent(world, eid, world.Ball)
  throw new Error(`addComponent(world, ${eid}, world.Ball): entity ${eid} is ${what}, which cannot also be a ball; make balls with addBall or throwBall (the entity is left as it was)`)
}
