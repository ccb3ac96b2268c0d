// The app's store (web/src/app/store.js): which changes make a new revision, results that belong to the
// revision they were made for, the work under way, and what subscribers hear.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Store } from '../../web/src/app/store.js';
import { newDesign } from '../../web/src/app/design.js';
import * as cmd from '../../web/src/app/commands.js';

const seam = { points: [{ face: 0, bary: [1, 0, 0] }, { face: 9, bary: [0, 1, 0] }], closed: false };

test('what the panels are made from makes a new revision; the cut files alone do not', () => {
  const store = new Store(newDesign('sphere'));
  const heard = [];
  store.subscribe((what) => heard.push(what));
  const start = store.revision;
  assert.equal(store.commit(cmd.addSeam(store.design, seam)), true, 'a seam');
  assert.equal(store.revision, start + 1);
  assert.equal(store.commit(cmd.setFabrication(store.design, { allowance: 12 })), false, 'the seam allowance');
  assert.equal(store.revision, start + 1);
  assert.equal(store.commit(cmd.setPressure(store.design, 2000)), true, 'the pressure');
  assert.equal(store.undo(), true, 'undoing the pressure');
  assert.equal(store.design.pressure, newDesign('sphere').pressure);
  assert.equal(store.undo(), false, 'undoing the allowance');
  assert.equal(store.redo(), false);
  assert.equal(store.amend(cmd.setSeamWeight(store.design, 0, 0.5)), true, 'a fix-up of the seams');
  assert.equal(store.history.past.length, 2, 'a fix-up is no step of its own');
  const cut = { ...store.design, target: { ...store.design.target, cutThinHandles: true } };
  assert.equal(store.commit(cut), true, "the target's thin handles cut");
  assert.equal(store.undo(), true, 'put back');
  const before = store.revision;
  store.setResolution(3000);
  assert.equal(store.revision, before + 1, 'another resolution');
  assert.ok(heard.length >= 8 && heard.every((w) => w === 'design'));
});

test('a result belongs to the revision it was made for', () => {
  const store = new Store(newDesign('sphere'));
  const revision = store.revision;
  store.commit(cmd.addSeam(store.design, seam)); // an edit while the panels were being made
  store.setResult('optimized', { patternText: 'old' }, revision);
  assert.equal(store.result('optimized'), null, 'made for the design before the edit');
  store.setResult('optimized', { patternText: 'new' });
  assert.equal(store.result('optimized').patternText, 'new');
  store.commit(cmd.setFabrication(store.design, { allowance: 3 }));
  assert.equal(store.result('optimized').patternText, 'new', 'the cut files changed, not the panels');
  store.commit(cmd.setHeight(store.design, 2));
  assert.equal(store.result('optimized'), null);
  store.undo();
  assert.equal(store.result('optimized'), null, 'undo is a new revision too: its panels are kept results or made again');
  store.clearResults();
  assert.equal(store.results.size, 0);
});

test('a result is kept by what it was made from: met again by undo and on its target opened again, the newest eight', () => {
  const store = new Store(cmd.addSeam(newDesign('sphere'), seam));
  const first = store.madeKey();
  store.keepResult(first, { patternText: 'one seam' });
  store.commit(cmd.setPressure(store.design, 2000));
  assert.notEqual(store.madeKey(), first, 'the pressure is part of it');
  assert.equal(store.keptResult(store.madeKey()), null);
  store.commit(cmd.setFabrication(store.design, { allowance: 12 }));
  store.undo();
  store.undo();
  assert.equal(store.madeKey(), first, 'undone to the same seams and physics');
  assert.equal(store.keptResult(store.madeKey()).patternText, 'one seam');
  store.setResolution(3000);
  assert.equal(store.keptResult(store.madeKey()), null, 'made at another resolution');
  for (let k = 0; k < 8; k++) store.keepResult(`other ${k}`, { patternText: String(k) });
  assert.equal(store.keptResult(first), null, 'eight newer: the oldest went');
  assert.equal(store.keptResult('other 0').patternText, '0');
  store.keepResult('other 8', { patternText: '8' });
  assert.equal(store.keptResult('other 1'), null, 'the oldest goes first');
  assert.equal(store.keptResult('other 0').patternText, '0', 'met again, it became the newest');
  const onSphere = store.madeKey();
  store.keepResult(onSphere, { patternText: 'on the sphere' });
  store.targetKey = 'another mesh';
  assert.equal(store.keptResult(store.madeKey()), null, 'the same design on another target mesh');
  store.targetKey = '';
  assert.equal(store.keptResult(store.madeKey()).patternText, 'on the sphere', 'its target opened again');
});

test('the optimized panels are shown once made, inflated and on screen with nothing under way', () => {
  const store = new Store(newDesign('sphere'));
  store.working('panels', +1);
  assert.equal(store.isWorking('panels'), true);
  assert.equal(store.isWorking(), true);
  store.setResult('optimized', { patternText: 'P' });
  store.show({ patternText: 'P', pattern: { panels: [] } });
  assert.equal(store.optimizedShown(), null, 'still optimizing');
  store.working('panels', -1);
  assert.equal(store.optimizedShown(), null, 'not inflated yet');
  store.working('inflation', +1);
  store.show({ inflated: { volume: 1 } });
  assert.equal(store.optimizedShown(), null, 'still inflating');
  store.working('inflation', -1);
  assert.equal(store.isWorking(), false);
  assert.equal(store.optimizedShown().inflated.volume, 1);
  store.show({ patternText: 'another pattern' });
  assert.equal(store.optimizedShown(), null, 'a pattern opened from a file is shown instead');
});

test('another history in place (the classroom walk) keeps the revision when the design is the same', () => {
  const store = new Store(cmd.addSeam(newDesign('sphere'), seam));
  store.commit(cmd.setPressure(store.design, 1500));
  const revision = store.revision;
  const designers = store.swapHistory();
  assert.equal(store.revision, revision);
  assert.equal(store.history.past.length, 0, 'the walk starts its own history');
  store.commit(newDesign('teddy'), { reset: true });
  assert.equal(store.revision, revision + 1);
  store.commit(designers.present, { reset: true });
  store.swapHistory(designers);
  assert.equal(store.history.past.length, 1, "the designer's undo steps are back");
  store.endStep();
  assert.equal(store.history.lastKey, null);
  store.setStatus('Ready');
  assert.equal(store.status, 'Ready');
});
