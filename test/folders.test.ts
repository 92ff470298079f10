/**
 * The folders of src/ import each other in no circle (type-only and dynamic imports count too): each stage
 * reads the ones below it, so a folder can be read, tested and changed knowing only those.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const SRC = fileURLToPath(new URL('../../src/', import.meta.url));
const IMPORT = /(?:import|export)\s+(?:type\s+)?[^'"]*?from\s+['"](\.[^'"]+)['"]|import\(\s*['"](\.[^'"]+)['"]\s*\)/g;

function sources(dir: string, out: string[] = []): string[] {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) sources(path, out);
    else if (name.endsWith('.ts')) out.push(path);
  }
  return out;
}

/** The top-level folder of a path in src/, or null for a file at its root (the entries). */
function folderOf(path: string): string | null {
  const parts = relative(SRC, path).split(/[\\/]/);
  return parts.length > 1 ? parts[0] : null;
}

/** Folder → folder → the imports that make the edge ("file → specifier"). */
function folderGraph(): Map<string, Map<string, string[]>> {
  const graph = new Map<string, Map<string, string[]>>();
  for (const file of sources(SRC)) {
    const from = folderOf(file);
    if (!from) continue;
    for (const m of readFileSync(file, 'utf8').matchAll(IMPORT)) {
      const spec = m[1] ?? m[2];
      const to = folderOf(resolve(dirname(file), spec));
      if (!to || to === from) continue;
      if (!graph.has(from)) graph.set(from, new Map());
      const edges = graph.get(from)!;
      edges.set(to, [...(edges.get(to) ?? []), `${relative(SRC, file)} → ${spec}`]);
    }
  }
  return graph;
}

/** A circle of folders (the first folder repeated at its end), or null. */
function findCircle(graph: Map<string, Map<string, string[]>>): string[] | null {
  const state = new Map<string, 'open' | 'done'>();
  const path: string[] = [];
  const visit = (f: string): string[] | null => {
    if (state.get(f) === 'done') return null;
    if (state.get(f) === 'open') return [...path.slice(path.indexOf(f)), f];
    state.set(f, 'open');
    path.push(f);
    for (const to of graph.get(f)?.keys() ?? []) {
      const circle = visit(to);
      if (circle) return circle;
    }
    path.pop();
    state.set(f, 'done');
    return null;
  };
  for (const f of graph.keys()) {
    const circle = visit(f);
    if (circle) return circle;
  }
  return null;
}

test('no two folders of src/ import each other, directly or round a circle', () => {
  const graph = folderGraph();
  assert.ok((graph.get('pipeline')?.size ?? 0) > 3, 'the imports are found');
  const circle = findCircle(graph);
  const why = circle?.slice(1).map((to, k) => `${circle[k]} → ${to}: ${graph.get(circle[k])!.get(to)!.join(', ')}`);
  assert.equal(circle, null, `folders in a circle:\n${why?.join('\n')}`);
});

test('the circle finder finds a circle', () => {
  const g = new Map([
    ['a', new Map([['b', ['x']]])],
    ['b', new Map([['c', ['y']]])],
    ['c', new Map([['a', ['z']]])],
  ]);
  assert.deepEqual(findCircle(g), ['a', 'b', 'c', 'a']);
  g.get('c')!.delete('a');
  assert.equal(findCircle(g), null);
});
