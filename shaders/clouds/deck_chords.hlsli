#ifndef FIRMAMENT_DECK_CHORDS_HLSLI
#define FIRMAMENT_DECK_CHORDS_HLSLI
// A particle's deck along one direction of the sun's ray (docs/clouds.md, "Deck diffusion"): the
// chords of other particles that the ray from the particle's centre crosses without a stretch of
// clear air between them and the particle longer than kDeckGapShare of the particle's half-width
// across the ray (through a shorter gap the diffuse light goes on into the next cloud; through a
// longer one it leaves by the gap's open sides). clouds/particle_opacity.hlsl meets the chords in
// its tile list's order, by the particles' centres, which is not the order of where they start:
// a wide particle met late may bridge a gap between chords met earlier. So the chords not yet
// joined to the deck wait as up to four separate runs, merged with each other and with the deck
// as later chords bridge them. With more than four runs waiting, the one starting farthest from
// the particle is dropped from the deck (its light still counts in the column). The CPU twin,
// src/reference/SunColumnTwin.cpp's deckDepth(), takes the union of every chord.

static const float kNoRun = 3.0e38;
// The longest gap the deck bridges, as a share of the particle's half-width across the sun's ray
// (src/clouds/LightSpace.h's kDeckGapShare; chosen by measurement, docs/clouds.md, "Deck diffusion").
static const float kDeckGapShare = 0.25;

struct DeckChords {
    float gap;     // the longest gap bridged (m)
    float reach;   // the deck covers [0, reach] along the ray
    float depth;   // its optical depth, the particle's own chord excluded
    float4 start;  // the waiting runs, kNoRun where empty
    float4 end;
    float4 runDepth;
};

// The deck of a particle whose own chord covers [0, ownReach] from its centre and whose half-width
// across the ray is `halfWidth`, nothing met yet.
DeckChords emptyDeck(float ownReach, float halfWidth) {
    DeckChords deck;
    deck.gap = kDeckGapShare * halfWidth;
    deck.reach = ownReach;
    deck.depth = 0.0;
    deck.start = kNoRun;
    deck.end = -kNoRun;
    deck.runDepth = 0.0;
    return deck;
}

// The waiting runs that the deck now reaches join it, and so on while it grows.
void absorbRuns(inout DeckChords deck) {
    [unroll] for (int round = 0; round < 4; ++round) {
        float4 joins = step(deck.start, deck.reach);
        if (!any(joins)) break;
        deck.reach = max(deck.reach, max(max(joins.x * deck.end.x, joins.y * deck.end.y), max(joins.z * deck.end.z, joins.w * deck.end.w)));
        deck.depth += dot(joins, deck.runDepth);
        deck.start = joins > 0.0 ? kNoRun : deck.start;
        deck.end = joins > 0.0 ? -kNoRun : deck.end;
        deck.runDepth = joins > 0.0 ? 0.0 : deck.runDepth;
    }
}

// A chord [start, end] of optical depth `depth` met along the ray. It is kept as starting a gap
// nearer, [start - gap, end], so that anything it overlaps is within a gap of it.
void addChord(inout DeckChords deck, float start, float end, float depth) {
    start -= deck.gap;
    if (start <= deck.reach) {
        deck.reach = max(deck.reach, end);
        deck.depth += depth;
        absorbRuns(deck);
        return;
    }
    // Past a gap for now: merged with every waiting run it overlaps, or a run of its own.
    float4 overlaps = step(deck.start, end) * step(start, deck.end);
    float mergedStart = start, mergedEnd = end, mergedDepth = depth;
    if (any(overlaps)) {
        mergedStart = min(start, min(min(overlaps.x > 0.0 ? deck.start.x : kNoRun, overlaps.y > 0.0 ? deck.start.y : kNoRun),
                                     min(overlaps.z > 0.0 ? deck.start.z : kNoRun, overlaps.w > 0.0 ? deck.start.w : kNoRun)));
        mergedEnd = max(end, max(max(overlaps.x * deck.end.x, overlaps.y * deck.end.y), max(overlaps.z * deck.end.z, overlaps.w * deck.end.w)));
        mergedDepth += dot(overlaps, deck.runDepth);
        deck.start = overlaps > 0.0 ? kNoRun : deck.start;
        deck.end = overlaps > 0.0 ? -kNoRun : deck.end;
        deck.runDepth = overlaps > 0.0 ? 0.0 : deck.runDepth;
    }
    // Its slot: an empty one, else the run starting farthest away, if this one starts nearer.
    float farthest = max(max(deck.start.x, deck.start.y), max(deck.start.z, deck.start.w));
    if (mergedStart >= farthest) return;
    float4 slot = deck.start.x == farthest ? float4(1, 0, 0, 0) : deck.start.y == farthest ? float4(0, 1, 0, 0)
                : deck.start.z == farthest ? float4(0, 0, 1, 0) : float4(0, 0, 0, 1);
    deck.start = slot > 0.0 ? mergedStart : deck.start;
    deck.end = slot > 0.0 ? mergedEnd : deck.end;
    deck.runDepth = slot > 0.0 ? mergedDepth : deck.runDepth;
}

#endif
