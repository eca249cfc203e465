// The throw controls: an aim angle and a power meter. Pointer (press-and-hold to charge, drag to aim,
// release to throw), keyboard (arrows aim, space charges) and the test hook all call the same methods,
// so a scripted throw goes through the same path as a played one.

/** Seconds for the meter to fill from 0 to 1; it then drains back (ping-pong) while held. */
export const CHARGE_SECONDS = 1.1
/** Largest aim, radians either side of straight up. */
export const MAX_AIM = 1.25
/**
 * Aim speed while an arrow key is held, rad/s, from AIM_HOLD s after the press on; the nudge of a single
 * press. A tap is one nudge at any frame rate (the sweep once began at the press, and a tap of a tenth of a
 * second turned the aim 3–4 nudges, more at a lower frame rate).
 */
export const AIM_RATE = 0.7
export const AIM_NUDGE = 0.01
export const AIM_HOLD = 0.25

export interface ThrowRequest {
  /** 0..1 */
  power: number
  /** radians, 0 = straight up the panel, positive toward +x */
  angle: number
}

export class ThrowInput {
  angle = 0
  power = 0
  charging = false
  private chargeStart = 0
  private held: number | null = null
  private left = false
  private right = false
  /** when the arrow key held now was pressed, s */
  private pressedAt = 0

  constructor(private readonly onThrow: (request: ThrowRequest) => void) {}

  setAim(angle: number): void {
    if (!Number.isFinite(angle)) return
    this.angle = Math.max(-MAX_AIM, Math.min(MAX_AIM, angle))
  }

  /** Aims from the launch point toward (x, y), in panel coordinates. */
  aimAt(x: number, y: number, launchX: number, launchY: number): void {
    const dx = x - launchX
    const dy = y - launchY
    if (dx * dx + dy * dy < 4) return
    this.setAim(Math.atan2(dx, -dy))
  }

  beginCharge(now: number): void {
    if (this.charging) return
    this.charging = true
    this.chargeStart = now
    this.power = 0
    this.held = null
  }

  /** Holds the meter at `power` until release (the test hook's way to charge exactly). */
  holdPower(power: number): void {
    if (!this.charging || !Number.isFinite(power)) return
    this.held = Math.max(0, Math.min(1, power))
    this.power = this.held
  }

  /** Throws with the current aim and charge. */
  release(now: number): void {
    if (!this.charging) return
    this.update(now, 0)
    this.charging = false
    this.held = null
    const request = { power: this.power, angle: this.angle }
    this.onThrow(request)
  }

  cancel(): void {
    this.charging = false
    this.held = null
    this.power = 0
  }

  /** Advances the meter and the held arrow keys. `now` and `dt` in seconds. */
  update(now: number, dt: number): void {
    if (this.left !== this.right) {
      // the part of this frame past the hold delay
      const from = Math.max(now - dt, this.pressedAt + AIM_HOLD)
      if (now > from) this.setAim(this.angle + (this.right ? 1 : -1) * AIM_RATE * (now - from))
    }
    if (!this.charging) return
    if (this.held !== null) {
      this.power = this.held
      return
    }
    const phase = ((now - this.chargeStart) / CHARGE_SECONDS) % 2
    this.power = phase <= 1 ? phase : 2 - phase
  }

  /** Keyboard: returns true when the key was used (the caller then prevents its default). */
  key(code: string, down: boolean, repeat: boolean, now: number): boolean {
    switch (code) {
      case 'ArrowLeft':
        if (down && !repeat && !this.left) this.press(now, -1)
        this.left = down
        return true
      case 'ArrowRight':
        if (down && !repeat && !this.right) this.press(now, 1)
        this.right = down
        return true
      case 'Space':
        if (down && !repeat) this.beginCharge(now)
        else if (!down) this.release(now)
        return true
      default:
        return false
    }
  }

  /** An arrow key pressed: one nudge now, a sweep if it is held past AIM_HOLD. */
  private press(now: number, sign: number): void {
    this.setAim(this.angle + sign * AIM_NUDGE)
    this.pressedAt = now
  }

  /** Clears held keys (the window lost focus). */
  blur(): void {
    this.left = false
    this.right = false
    this.cancel()
  }
}
