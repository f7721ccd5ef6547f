// GeoJSON / TopoJSON -> rings. Polygons and MultiPolygons (any nesting of Features,
// FeatureCollections and GeometryCollections) keep every ring; holes come from the even-odd
// rule, so ring orientation (which RFC 7946 prescribes but older files ignore) does not matter.
// Longitude/latitude input is projected, because meshing degrees directly stretches shapes
// east-west by 1/cos(latitude) and would make the "acute" angles wrong on the map.
import { feature } from '../vendor/topojson-client/index.js';
import { cleanRings, ringsBounds } from '../geometry.js';

const EARTH_RADIUS_KM = 6371.0088;

export function isGeoJson(obj) {
  return obj && typeof obj === 'object' &&
    ['FeatureCollection', 'Feature', 'GeometryCollection', 'Polygon', 'MultiPolygon', 'Topology']
      .includes(obj.type);
}

function collectPolygons(g, out) {
  if (!g) return;
  switch (g.type) {
    case 'FeatureCollection': g.features.forEach((f) => collectPolygons(f, out)); break;
    case 'Feature': collectPolygons(g.geometry, out); break;
    case 'GeometryCollection': g.geometries.forEach((h) => collectPolygons(h, out)); break;
    case 'Polygon': out.push(...g.coordinates); break;
    case 'MultiPolygon': g.coordinates.forEach((p) => out.push(...p)); break;
    default: break;  // points and lines bound no area
  }
}

function topologyToGeoJson(topo) {
  const features = Object.values(topo.objects || {}).map((o) => feature(topo, o));
  return { type: 'FeatureCollection', features };
}

// Lambert azimuthal equal-area, centred on the data: areas are true (so a max-area bound reads
// in km^2) and shapes are undistorted near the centre, which is all a country or a lake needs.
export function projectLonLat(rings) {
  const b = ringsBounds(rings);
  const rad = Math.PI / 180;
  const lam0 = ((b.x0 + b.x1) / 2) * rad, phi0 = ((b.y0 + b.y1) / 2) * rad;
  const sin0 = Math.sin(phi0), cos0 = Math.cos(phi0);
  return rings.map((ring) => ring.map(([lon, lat]) => {
    const lam = lon * rad - lam0, phi = lat * rad;
    const sinp = Math.sin(phi), cosp = Math.cos(phi), cosl = Math.cos(lam);
    const k = Math.sqrt(2 / Math.max(1e-12, 1 + sin0 * sinp + cos0 * cosp * cosl));
    return [EARTH_RADIUS_KM * k * cosp * Math.sin(lam),
      EARTH_RADIUS_KM * k * (cos0 * sinp - sin0 * cosp * cosl)];
  }));
}

function looksLikeLonLat(rings) {
  const b = ringsBounds(rings);
  return b.x0 >= -180 && b.x1 <= 180 && b.y0 >= -90 && b.y1 <= 90;
}

// Returns { rings, projected, polygons } or throws with a message for the user.
export function geoJsonToRings(obj, { project = 'auto' } = {}) {
  const geo = obj.type === 'Topology' ? topologyToGeoJson(obj) : obj;
  const raw = [];
  collectPolygons(geo, raw);
  let rings = cleanRings(raw);
  if (!rings.length) throw new Error('no Polygon or MultiPolygon with area in this file');
  const projected = project === 'always' || (project === 'auto' && looksLikeLonLat(rings));
  if (projected) rings = cleanRings(projectLonLat(rings));
  return { rings, projected };
}
