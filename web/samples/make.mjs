// Regenerates the bundled sample maps (GeoJSON, lon/lat) from the npm packages world-atlas
// (Natural Earth, public domain) and us-atlas (US Census Bureau cartographic boundaries, public
// domain). Run from the repository root after `npm install`:  node web/samples/make.mjs
// The page loads the results through its ordinary GeoJSON loader, so the samples exercise the
// same code path as a user's upload.
import { readFileSync, writeFileSync } from 'node:fs';
import { feature } from 'topojson-client';

const read = (p) => JSON.parse(readFileSync(new URL(`../../node_modules/${p}`, import.meta.url)));
const world = read('world-atlas/countries-50m.json');
const states = read('us-atlas/states-10m.json');

// id: ISO 3166 numeric (countries) or FIPS (states), as the atlases key them.
const SAMPLES = [
  { file: 'turkey', topo: world, object: 'countries', id: '792' },
  { file: 'florida', topo: states, object: 'states', id: '12' },
  { file: 'south-africa', topo: world, object: 'countries', id: '710' },
  { file: 'italy', topo: world, object: 'countries', id: '380' },
  { file: 'iceland', topo: world, object: 'countries', id: '352' },
];

// Five decimals of a degree is about a metre: far below these maps' own resolution.
const round = (c) => (Array.isArray(c[0]) ? c.map(round) : c.map((v) => Math.round(v * 1e5) / 1e5));

for (const s of SAMPLES) {
  const f = feature(s.topo, s.topo.objects[s.object]).features.find((g) => g.id === s.id);
  if (!f) throw new Error(`${s.file}: id ${s.id} not found`);
  const out = {
    type: 'Feature',
    properties: { name: f.properties.name },
    geometry: { type: f.geometry.type, coordinates: round(f.geometry.coordinates) },
  };
  writeFileSync(new URL(`./${s.file}.geojson`, import.meta.url), JSON.stringify(out) + '\n');
  console.log(`${s.file}.geojson: ${f.properties.name}`);
}
