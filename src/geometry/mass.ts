import { checkNonNegative } from '../core/errors';
import { arcTangent2 } from '../math/arc-tangent';
import { type Capsule, type Geometry, type MassData, type Polygon, ShapeKind } from './types';

const PI = Math.PI;

/**
 * Mass properties of `g` at `density` (kg/m^2): mass, local centre of mass and the rotational
 * inertia about that centre. Segments have no area and so no mass.
 */
export function computeMass(g: Geometry, density: number, out: MassData): MassData {
  checkNonNegative('density', density);
  switch (g.kind) {
    case ShapeKind.CIRCLE: {
      const rr = g.radius * g.radius;
      out.mass = density * PI * rr;
      out.centerX = g.center.x;
      out.centerY = g.center.y;
      out.inertia = 0.5 * out.mass * rr;
      return out;
    }
    case ShapeKind.CAPSULE:
      return capsuleMass(g, density, out);
    case ShapeKind.POLYGON:
      return polygonMass(g, density, out);
    default:
      out.mass = 0;
      out.centerX = 0.5 * (g.point1.x + g.point2.x);
      out.centerY = 0.5 * (g.point1.y + g.point2.y);
      out.inertia = 0;
      return out;
  }
}

/** A rectangle (length L, width 2r) plus two half discs whose centroids sit 4r/(3 pi) beyond its ends. */
function capsuleMass(g: Capsule, density: number, out: MassData): MassData {
  const r = g.radius;
  const dx = g.center2.x - g.center1.x;
  const dy = g.center2.y - g.center1.y;
  const ll = dx * dx + dy * dy;
  const length = Math.sqrt(ll);
  const rectMass = density * 2 * r * length;
  const discMass = density * PI * r * r;
  out.mass = rectMass + discMass;
  out.centerX = 0.5 * (g.center1.x + g.center2.x);
  out.centerY = 0.5 * (g.center1.y + g.center2.y);
  // each half disc: I_own = m/2 (r^2/2 - d^2), shifted by (L/2 + d): together m (r^2/2 + L^2/4 + L d)
  const d = (4 * r) / (3 * PI);
  const rectInertia = (rectMass * (ll + 4 * r * r)) / 12;
  const discInertia = discMass * (0.5 * r * r + 0.25 * ll + length * d);
  out.inertia = rectInertia + discInertia;
  return out;
}

/**
 * Exact for sharp and rounded polygons: the rounded polygon is split into the core polygon, one
 * rectangle (edge x radius) outside each edge and one circular sector at each vertex. Area, first
 * and second moments are summed about the vertex average (for precision), then moved to the centroid.
 */
function polygonMass(g: Polygon, density: number, out: MassData): MassData {
  const n = g.count;
  const v = g.vertices;
  const r = g.radius;
  let ox = 0;
  let oy = 0;
  for (let i = 0; i < n; i++) {
    ox += v[i].x;
    oy += v[i].y;
  }
  ox /= n;
  oy /= n;

  let area = 0;
  let mx = 0; // first moment about o
  let my = 0;
  let polar = 0; // second moment about o
  for (let i = 0; i < n; i++) {
    const ax = v[i].x - ox;
    const ay = v[i].y - oy;
    const j = i + 1 === n ? 0 : i + 1;
    const bx = v[j].x - ox;
    const by = v[j].y - oy;
    // triangle (o, a, b)
    const cross = ax * by - ay * bx;
    area += 0.5 * cross;
    mx += (cross * (ax + bx)) / 6;
    my += (cross * (ay + by)) / 6;
    polar += (cross * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by)) / 12;
    if (r > 0) {
      // rectangle outside edge a-b: its centre, area L r and own polar moment A (L^2 + r^2) / 12
      const nx = g.normals[i].x;
      const ny = g.normals[i].y;
      const ex = bx - ax;
      const ey = by - ay;
      const ll = ex * ex + ey * ey;
      const rectArea = Math.sqrt(ll) * r;
      const cx = 0.5 * (ax + bx + r * nx);
      const cy = 0.5 * (ay + by + r * ny);
      area += rectArea;
      mx += rectArea * cx;
      my += rectArea * cy;
      polar += rectArea * ((ll + r * r) / 12 + cx * cx + cy * cy);
    }
  }
  if (r > 0) {
    const rr = r * r;
    for (let i = 0; i < n; i++) {
      // sector at vertex i between the normals of edges i-1 and i
      const p = g.normals[i === 0 ? n - 1 : i - 1];
      const q = g.normals[i];
      const angle = arcTangent2(p.x * q.y - p.y * q.x, p.x * q.x + p.y * q.y);
      const sectorArea = 0.5 * angle * rr;
      // first moment about the apex: (2 r^3 / 3) sin(angle/2) along the bisector = (r^3/3) * cw-perp(q - p)
      const fx = (rr * r * (q.y - p.y)) / 3;
      const fy = (-rr * r * (q.x - p.x)) / 3;
      const ax = v[i].x - ox;
      const ay = v[i].y - oy;
      area += sectorArea;
      mx += sectorArea * ax + fx;
      my += sectorArea * ay + fy;
      polar += sectorArea * (ax * ax + ay * ay) + 2 * (ax * fx + ay * fy) + 0.25 * angle * rr * rr;
    }
  }
  const cx = mx / area;
  const cy = my / area;
  out.mass = density * area;
  out.centerX = ox + cx;
  out.centerY = oy + cy;
  out.inertia = density * (polar - area * (cx * cx + cy * cy));
  return out;
}
