package org.kdtree.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.BitSet;
import org.junit.jupiter.api.Test;

class TileOrderTest {
    @Test void everyTileIsTakenExactlyOnce() {
        for (int tiles = 1; tiles <= 600; tiles++) {
            TileOrder order = new TileOrder(tiles);
            BitSet seen = new BitSet(tiles);
            for (int k = 0; k < tiles; k++) {
                int t = order.tile(k);
                assertThat(t).as("%d tiles, %d-th", tiles, k).isBetween(0, tiles - 1);
                assertThat(seen.get(t)).as("%d tiles: tile %d taken twice", tiles, t).isFalse();
                seen.set(t);
            }
        }
    }

    /** The first tenth of the tiles taken reaches every quarter of the image's rows: not the top rows first. */
    @Test void theFirstTilesLieAllOverTheImage() {
        int[][] grids = {{16, 16}, {25, 19}, {7, 40}, {40, 7}};
        for (int[] g : grids) {
            int tilesX = g[0], tilesY = g[1], tiles = tilesX * tilesY;
            TileOrder order = new TileOrder(tiles);
            boolean[] quarter = new boolean[4];
            for (int k = 0; k < Math.max(4, tiles / 10); k++) quarter[4 * (order.tile(k) / tilesX) / tilesY] = true;
            assertThat(quarter).as("%d x %d tiles", tilesX, tilesY).containsOnly(true);
        }
    }
}
