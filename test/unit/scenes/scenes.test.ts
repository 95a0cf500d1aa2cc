import { describe, expect, it } from 'vitest';
import {
  benchmarkScenes,
  bodyCentroid,
  bodyMass,
  cardHouse,
  chain,
  highMassRatio,
  jointGrid,
  manyPyramids,
  pyramid,
  rain,
  sceneBuilders,
  tumbler,
  verticalStack,
} from '../../../scenes/index';
import type { Scene } from '../../../scenes/types';
import { overlapDepth, worldPolygon } from './geometry-helpers';

const dynamic = (scene: Scene) => scene.bodies.filter((b) => b.type === 'dynamic');

/** largest overlap depth between any two box/polygon shapes of the scene's dynamic and static bodies */
function deepestOverlap(scene: Scene): number {
  const polygons = scene.bodies.flatMap((body, i) =>
    body.shapes
      .filter((s) => s.kind === 'box' || s.kind === 'polygon')
      .map((s) => ({ i, points: worldPolygon(body, s) })),
  );
  let deepest = 0;
  for (let a = 0; a < polygons.length; a++) {
    for (let b = a + 1; b < polygons.length; b++) {
      if (polygons[a].i === polygons[b].i) continue;
      deepest = Math.max(deepest, overlapDepth(polygons[a].points, polygons[b].points));
    }
  }
  return deepest;
}

describe('scene registry', () => {
  it('has every benchmark scene', () => {
    for (const name of benchmarkScenes) expect(sceneBuilders[name]).toBeTypeOf('function');
  });

  it.each(Object.keys(sceneBuilders))('%s is valid and deterministic, full and quick', (name) => {
    for (const quick of [false, true]) {
      const scene = sceneBuilders[name](quick);
      expect(scene).toEqual(sceneBuilders[name](quick));
      for (const j of scene.joints) {
        expect(j.bodyA).toBeGreaterThanOrEqual(0);
        expect(j.bodyB).toBeLessThan(scene.bodies.length);
        expect(j.bodyA).not.toBe(j.bodyB);
      }
      for (const body of dynamic(scene)) {
        expect(bodyMass(body)).toBeGreaterThan(0);
        // every dynamic body has its centre of mass at its origin, so adapters need no offset
        const c = bodyCentroid(body);
        expect(Math.hypot(c.x, c.y)).toBeLessThan(1e-9);
      }
    }
  });
});

describe('pyramid', () => {
  it('has base * (base + 1) / 2 boxes of 1 kg on a static ground', () => {
    const scene = pyramid({ base: 40 });
    expect(dynamic(scene)).toHaveLength(820);
    for (const b of dynamic(scene)) expect(bodyMass(b)).toBeCloseTo(1, 12);
    expect(scene.bodies[0].type).toBe('static');
    expect(dynamic(pyramid({ base: 100 }))).toHaveLength(5050);
  });

  it('starts with no two boxes overlapping and the bottom row on the ground', () => {
    const scene = pyramid({ base: 12 });
    expect(deepestOverlap(scene)).toBeLessThanOrEqual(1e-12);
    const bottom = Math.min(...dynamic(scene).map((b) => b.position.y));
    expect(bottom).toBe(0.5);
  });

  it('many pyramids: 20 pyramids of base 10 make 1,100 boxes that do not overlap', () => {
    const scene = manyPyramids();
    expect(dynamic(scene)).toHaveLength(1100);
    expect(deepestOverlap(manyPyramids({ count: 3, base: 10 }))).toBeLessThanOrEqual(1e-12);
  });
});

describe('small scenes', () => {
  it('vertical stack: n boxes of 1 kg', () => {
    const scene = verticalStack({ count: 20 });
    expect(dynamic(scene)).toHaveLength(20);
    expect(deepestOverlap(scene)).toBeLessThanOrEqual(1e-12);
  });

  it('mass ratio: 100 kg on 1 kg', () => {
    const scene = highMassRatio();
    const mass = (tag: string) => bodyMass(scene.bodies.find((b) => b.tag === tag)!);
    expect(mass('light')).toBeCloseTo(1, 12);
    expect(mass('heavy')).toBeCloseTo(100, 12);
  });

  it('card house: cards touch but never overlap', () => {
    const scene = cardHouse({ levels: 3 });
    expect(dynamic(scene)).toHaveLength(2 * (3 + 2 + 1) + (2 + 1));
    expect(deepestOverlap(scene)).toBeLessThanOrEqual(1e-9);
  });
});

describe('rain and tumbler', () => {
  it('rain drops every kind of shape, none overlapping, all inside the container', () => {
    const scene = rain({ count: 1000 });
    const drops = dynamic(scene);
    expect(drops).toHaveLength(1000);
    expect(new Set(drops.map((b) => b.shapes[0].kind))).toEqual(
      new Set(['circle', 'box', 'capsule', 'polygon']),
    );
    // every drop fits in a 0.4 m radius; centres are at least 0.8 m apart
    for (let i = 0; i < drops.length; i++) {
      for (let k = i + 1; k < drops.length; k++) {
        const d = Math.hypot(
          drops[i].position.x - drops[k].position.x,
          drops[i].position.y - drops[k].position.y,
        );
        if (d < 0.8) throw new Error(`drops ${i} and ${k} are ${d} m apart`);
      }
    }
    const box = scene.containment!;
    for (const b of drops) expect(b.position.x > box.lower.x && b.position.x < box.upper.x).toBe(true);
  });

  it('tumbler: a turning kinematic drum of four walls holding 500 boxes', () => {
    const scene = tumbler({ count: 500 });
    const drum = scene.bodies[0];
    expect(drum.type).toBe('kinematic');
    expect(drum.shapes).toHaveLength(4);
    expect(drum.angularVelocity).toBe(0.25);
    expect(dynamic(scene)).toHaveLength(500);
    expect(deepestOverlap(scene)).toBeLessThanOrEqual(1e-12);
  });
});

describe('jointed scenes', () => {
  it('joint grid: 40 x 40 bodies, links to right and lower neighbours, top row pinned', () => {
    const scene = jointGrid({ size: 40 });
    expect(dynamic(scene)).toHaveLength(1600);
    expect(scene.joints).toHaveLength(40 + 2 * 40 * 39);
    expect(scene.joints.filter((j) => scene.bodies[j.bodyA].type === 'static')).toHaveLength(40);
  });

  it('chain: 100 links of 1 kg, 0.5 m pin to pin, and a 100 kg ball', () => {
    const scene = chain({ links: 100 });
    const links = scene.bodies.filter((b) => b.tag === 'link');
    expect(links).toHaveLength(100);
    for (const link of links) expect(bodyMass(link)).toBeCloseTo(1, 12);
    expect(bodyMass(scene.bodies.find((b) => b.tag === 'ball')!)).toBeCloseTo(100, 12);
    expect(scene.joints).toHaveLength(101);
    scene.joints.forEach((j, i) => {
      expect(j.type === 'revolute' && j.anchor.x).toBeCloseTo(0.5 * i, 12);
    });
  });
});
