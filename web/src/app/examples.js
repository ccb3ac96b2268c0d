// Built-in example targets (files in web/public/examples, credits in web/public/examples/CREDITS.md). front: the way
// the model faces in its file, where that is not +Z (the default view looks at it from there).
export const EXAMPLES = [
  { id: 'spot', name: 'Spot the cow', file: 'spot.obj', height: 0.6, front: [0, 0, -1], credit: 'Keenan Crane, public domain (CC0)' },
  { id: 'blub', name: 'Blub the fish', file: 'blub.obj', height: 0.5, credit: 'Keenan Crane, public domain' },
  { id: 'sphere', name: 'Sphere', file: 'sphere.obj', height: 0.5, credit: 'Oded Stein, CC BY 4.0' },
  { id: 'penguin', name: 'Penguin', file: 'penguin.obj', height: 0.9, credit: 'Oded Stein, CC BY 4.0' },
  { id: 'koala', name: 'Koala', file: 'koala.obj', height: 0.4, credit: 'YahooJAPAN (Thingiverse thing:182225), remeshed by Oded Stein, CC BY 3.0' },
];

export const DEFAULT_EXAMPLE = 'spot';

export function findExample(id) {
  return EXAMPLES.find((e) => e.id === id) ?? null;
}
