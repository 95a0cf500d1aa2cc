/** Measures a page's layout for the e2e tests: boxes that overlap, and text that wraps word by word. */
import type { Page } from 'playwright-core';

export interface LayoutReport {
  /** pairs of boxes (neither inside the other in the DOM) that share more than a pixel */
  overlaps: string[];
  /** text broken into lines of one or two words, or a one-line control on two lines */
  wrapped: string[];
  /** elements reaching past the viewport's right edge */
  outside: string[];
  /** how many boxes were measured */
  measured: number;
}

/**
 * `boxes`: selectors of the elements that must not overlap each other (every match counts);
 * `oneLine`: selectors of controls that must stay on one line; `prose`: selectors of text that may wrap,
 * but by more than two words a line.
 */
export function measureLayout(
  page: Page,
  selectors: { boxes: string[]; oneLine: string[]; prose: string[] },
): Promise<LayoutReport> {
  return page.evaluate(({ boxes, oneLine, prose }) => {
    const shown = (el: Element): boolean => {
      const rect = el.getBoundingClientRect();
      return rect.width > 0 && rect.height > 0 && getComputedStyle(el).visibility !== 'hidden';
    };
    const name = (el: Element): string => {
      const id = el.id ? `#${el.id}` : '';
      const cls = el.classList.length > 0 ? `.${Array.from(el.classList).join('.')}` : '';
      const text = (el.textContent ?? '').trim().slice(0, 24);
      return `${el.tagName.toLowerCase()}${id}${cls} "${text}"`;
    };
    const all = (list: string[]): Element[] => [
      ...new Set(list.flatMap((s) => Array.from(document.querySelectorAll(s))).filter(shown)),
    ];
    const report = {
      overlaps: [] as string[],
      wrapped: [] as string[],
      outside: [] as string[],
      measured: 0,
    };
    const measured = all(boxes);
    report.measured = measured.length;
    for (let i = 0; i < measured.length; i++) {
      const a = measured[i];
      const ra = a.getBoundingClientRect();
      if (ra.right > window.innerWidth + 0.5) report.outside.push(name(a));
      for (let j = i + 1; j < measured.length; j++) {
        const b = measured[j];
        if (a.contains(b) || b.contains(a)) continue;
        const rb = b.getBoundingClientRect();
        const w = Math.min(ra.right, rb.right) - Math.max(ra.left, rb.left);
        const h = Math.min(ra.bottom, rb.bottom) - Math.max(ra.top, rb.top);
        if (w > 1 && h > 1)
          report.overlaps.push(`${name(a)} and ${name(b)} (${w.toFixed(0)}×${h.toFixed(0)})`);
      }
    }
    /**
     * the lines a text takes: the tops of its text's fragments (a select's options left out), those
     * within a few pixels of each other one line
     */
    const lines = (el: Element): number => {
      const tops: number[] = [];
      const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT);
      const range = document.createRange();
      for (let node = walker.nextNode(); node; node = walker.nextNode()) {
        if (node.parentElement?.closest('select') || !node.textContent?.trim()) continue;
        range.selectNodeContents(node);
        for (const r of Array.from(range.getClientRects())) if (r.width > 0) tops.push(r.top);
      }
      tops.sort((x, y) => x - y);
      let n = 0;
      let last = Number.NEGATIVE_INFINITY;
      for (const top of tops) {
        if (top - last > 4) n++;
        last = top;
      }
      return n;
    };
    for (const el of all(oneLine)) {
      if (lines(el) > 1) report.wrapped.push(`${name(el)}: ${lines(el)} lines`);
    }
    for (const el of all(prose)) {
      const words = (el.textContent ?? '').trim().split(/\s+/).length;
      const n = lines(el);
      if (n > 1 && words / n < 2.5) report.wrapped.push(`${name(el)}: ${words} words on ${n} lines`);
    }
    return report;
  }, selectors);
}
