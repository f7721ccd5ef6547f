// A small CG:SHOP 2025 instance made by the tests themselves (the same one as
// tests/cpp/test_vocabulary.cpp): a 12-gon with integer corners and 20 points a little inside
// its edges, where exact altitude feet pay off. Integer arithmetic only.
//   node tests/js/generated-instance.mjs > FILE   writes it
export function generatedInstance() {
  const cx = [2995, 2812, 2411, 1900, 1416, 1088, 1005, 1188, 1589, 2100, 2584, 2912];
  const cy = [2070, 2409, 2638, 2697, 2568, 2288, 1930, 1591, 1362, 1303, 1432, 1712];
  const xs = [...cx], ys = [...cy];
  let seed = 7n;
  const next = () => (seed = (seed * 48271n) % 2147483647n);
  const div = (a, b) => (a - (a % b)) / b;  // BigInt division truncates like C++'s
  for (let k = 0; k < 20; ++k) {
    const i = k % 12, j = (i + 1) % 12;
    const t = 20n + (next() % 61n), inward = 1n + (next() % 4n);
    let x = BigInt(cx[i]) + div(t * BigInt(cx[j] - cx[i]), 100n);
    let y = BigInt(cy[i]) + div(t * BigInt(cy[j] - cy[i]), 100n);
    x += div((2000n - x) * inward, 100n);
    y += div((2000n - y) * inward, 100n);
    xs.push(Number(x));
    ys.push(Number(y));
  }
  return JSON.stringify({
    instance_uid: 'generated_12', num_points: xs.length, points_x: xs, points_y: ys,
    region_boundary: [...Array(12).keys()], num_constraints: 0, additional_constraints: [],
  });
}

if (import.meta.url === `file://${process.argv[1]}`) process.stdout.write(generatedInstance() + '\n');
