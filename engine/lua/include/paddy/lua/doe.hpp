// Lua 5.4 binding of paddy::doe, opened with require("paddy.doe") once the engine registers
// luaopen_paddy_doe in package.preload. All functions take one options table; results mirror the
// JSON documents of docs/doe.md (JSON null becomes nil). Errors are raised with a message
// "paddy.doe.<function>: <reason>".
//   design{type="bbd"|"pb"|"ccd"|"factorial", factors=N | names={...}, levels={A={lo,hi}},
//          center=N, replicates=N, seed=S, alpha=number|"rotatable"|"face", ccd_type=...,
//          runs=N, generators={"D=ABC"}}             -> {factors=..., runs={{run,std,type,coded,real}}}
//   analyze{data={{A=..,B=..,Y=..},...}, factors={...}, responses={...}, model="quadratic",
//           levels={A={lo,hi}}}                       -> analysis table (JSON "responses", ...)
//   optimize{fit=<analysis>, goals={"Y=target:231", {response="Y2", goal="max", lower=, upper=,
//            target=, weight=, weight2=, importance=}}, bounds={A={lo,hi}}, starts=, seed=}
//                                                     -> {solutions={{factors,predicted,desirability}}}
//   steepest_ascent{factors={{name=,low=,high=}}, coefficients={b1,...}, descent=bool, steps=N,
//           key="A", step=S, real=bool, real_steps={...}, origin={...}} -> {{step, coded, real}}
#pragma once

struct lua_State;

extern "C" int luaopen_paddy_doe(lua_State* L);
