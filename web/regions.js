// Regions: the input's regional attributes (a .poly's regional attributes, JSON "regions")
// come back as one attribute per triangle (mesh().triangleAttributes). With more than one
// distinct value the view can colour the triangles by region instead of by largest angle.

// Okabe and Ito's colour-blind-safe categorical palette (Color Universal Design, 2008), in an
// order that keeps neighbours apart; past eight regions the colours repeat, and the legend
// says so.
export const REGION_COLORS = ['#56b4e9', '#e69f00', '#009e73', '#f0e442', '#0072b2', '#d55e00', '#cc79a7', '#999999'];

// Returns null when the mesh has no regions or only one attribute value; otherwise
// { values: the distinct attributes ascending, cls: Uint8Array palette index per triangle,
// counts: triangles per value, colors: one per value }.
export function regionsOf(attributes) {
  if (!attributes || !attributes.length) return null;
  const seen = new Map();
  for (let i = 0; i < attributes.length; i++) {
    const a = attributes[i];
    seen.set(a, (seen.get(a) || 0) + 1);
  }
  if (seen.size < 2) return null;
  const values = [...seen.keys()].sort((a, b) => a - b);
  const index = new Map(values.map((v, k) => [v, k]));
  const K = REGION_COLORS.length;
  const cls = new Uint8Array(attributes.length);
  for (let i = 0; i < attributes.length; i++) cls[i] = index.get(attributes[i]) % K;
  // One colour per palette slot: the view fills triangles by slot (values past the palette
  // share their slot's colour).
  return { values, cls, counts: values.map((v) => seen.get(v)), colors: REGION_COLORS.slice(0, Math.min(K, values.length)) };
}
