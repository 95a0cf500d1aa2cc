/**
 * Sound effects made on the spot with Web Audio (no files): the band's twang, thuds and clinks by
 * material, a pop, a little tune for a win. Muted until the player switches sound on; the audio
 * context is made then (browsers want a click before any sound).
 */
import type { Material } from './levels';

export class Sounds {
  private context: AudioContext | null = null;
  private master: GainNode | null = null;
  private noise: AudioBuffer | null = null;
  private muted = true;
  /** the context's time of the last hit sound: hits in a pile come in bursts */
  private lastHit = 0;

  get on(): boolean {
    return !this.muted;
  }

  /** Switches sound on or off (call it from a click or a key press). */
  setOn(on: boolean): void {
    this.muted = !on;
    if (on && !this.context) {
      const Context =
        window.AudioContext ??
        (window as unknown as { webkitAudioContext?: typeof AudioContext }).webkitAudioContext;
      if (!Context) return;
      const context = new Context();
      this.context = context;
      this.master = context.createGain();
      this.master.gain.value = 0.5;
      this.master.connect(context.destination);
      const length = Math.floor(context.sampleRate * 0.5);
      const buffer = context.createBuffer(1, length, context.sampleRate);
      const data = buffer.getChannelData(0);
      let seed = 1;
      for (let i = 0; i < length; i++) {
        seed = (seed * 16807) % 2147483647;
        data[i] = (seed / 2147483647) * 2 - 1;
      }
      this.noise = buffer;
    }
    if (on) void this.context?.resume();
  }

  dispose(): void {
    void this.context?.close();
    this.context = null;
  }

  private ready(): AudioContext | null {
    return this.muted || !this.context || this.context.state !== 'running' ? null : this.context;
  }

  /** a burst of filtered noise */
  private burst(type: BiquadFilterType, from: number, to: number, seconds: number, volume: number): void {
    const ctx = this.ready();
    if (!ctx || !this.noise || !this.master) return;
    const t = ctx.currentTime;
    const source = ctx.createBufferSource();
    source.buffer = this.noise;
    const filter = ctx.createBiquadFilter();
    filter.type = type;
    filter.frequency.setValueAtTime(from, t);
    filter.frequency.exponentialRampToValueAtTime(to, t + seconds);
    filter.Q.value = 1.5;
    const gain = ctx.createGain();
    gain.gain.setValueAtTime(volume, t);
    gain.gain.exponentialRampToValueAtTime(0.001, t + seconds);
    source.connect(filter).connect(gain).connect(this.master);
    source.start(t, Math.random() * 0.2, seconds);
  }

  /** a tone sliding from one pitch to another */
  private tone(
    wave: OscillatorType,
    from: number,
    to: number,
    seconds: number,
    volume: number,
    delay = 0,
  ): void {
    const ctx = this.ready();
    if (!ctx || !this.master) return;
    const t = ctx.currentTime + delay;
    const osc = ctx.createOscillator();
    osc.type = wave;
    osc.frequency.setValueAtTime(from, t);
    osc.frequency.exponentialRampToValueAtTime(to, t + seconds);
    const gain = ctx.createGain();
    gain.gain.setValueAtTime(0.0001, t);
    gain.gain.exponentialRampToValueAtTime(volume, t + 0.01);
    gain.gain.exponentialRampToValueAtTime(0.001, t + seconds);
    osc.connect(gain).connect(this.master);
    osc.start(t);
    osc.stop(t + seconds + 0.02);
  }

  launch(strength: number): void {
    this.tone('triangle', 180, 90, 0.25, 0.3 * strength + 0.1);
    this.burst('bandpass', 500, 2500, 0.35, 0.5 * strength + 0.1);
  }

  stretch(): void {
    this.tone('sawtooth', 90, 140, 0.12, 0.05);
  }

  trick(): void {
    this.tone('square', 500, 1400, 0.18, 0.12);
    this.burst('highpass', 1500, 4000, 0.2, 0.2);
  }

  hit(material: Material | 'target' | 'bird', strength: number): void {
    const ctx = this.ready();
    if (!ctx || ctx.currentTime - this.lastHit < 0.05) return;
    this.lastHit = ctx.currentTime;
    const v = Math.min(1, strength / 12);
    if (material === 'wood') {
      this.tone('triangle', 220, 140, 0.12, 0.4 * v);
      this.burst('bandpass', 700, 300, 0.1, 0.5 * v);
    } else if (material === 'stone') {
      this.tone('sine', 110, 60, 0.18, 0.6 * v);
      this.burst('lowpass', 400, 120, 0.15, 0.6 * v);
    } else if (material === 'ice') {
      this.tone('sine', 1900, 1700, 0.2, 0.2 * v);
      this.tone('sine', 2900, 2600, 0.15, 0.12 * v);
    } else if (material === 'target') {
      this.tone('square', 420, 300, 0.1, 0.1 * v);
    } else {
      this.burst('lowpass', 600, 200, 0.08, 0.3 * v);
    }
  }

  crash(material: Material): void {
    if (material === 'ice') {
      for (let i = 0; i < 4; i++) this.tone('sine', 1800 + i * 450, 1500 + i * 300, 0.25, 0.1, i * 0.03);
      this.burst('highpass', 3000, 1500, 0.3, 0.4);
    } else if (material === 'stone') {
      this.burst('lowpass', 800, 100, 0.5, 0.8);
      this.tone('sine', 90, 40, 0.4, 0.5);
    } else {
      this.burst('bandpass', 900, 200, 0.35, 0.7);
      this.tone('triangle', 160, 70, 0.25, 0.3);
    }
  }

  pop(): void {
    this.tone('sine', 300, 1100, 0.15, 0.35);
    this.burst('bandpass', 2000, 800, 0.15, 0.3);
  }

  gone(): void {
    this.burst('highpass', 2000, 800, 0.2, 0.15);
  }

  win(): void {
    const notes = [523, 659, 784, 1047];
    for (let i = 0; i < notes.length; i++) this.tone('triangle', notes[i], notes[i], 0.3, 0.25, i * 0.12);
  }

  lose(): void {
    const notes = [392, 330, 262];
    for (let i = 0; i < notes.length; i++)
      this.tone('triangle', notes[i], notes[i] * 0.97, 0.35, 0.2, i * 0.18);
  }
}
