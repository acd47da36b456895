//===- StdTypes.cpp - The standard library types symcr knows
//----------------===//
//
// See TypeWalker.h.
//
//===----------------------------------------------------------------------===//
#include "TypeWalker.h"
#include "NameIndex.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Attr.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/Mangle.h"
#include "clang/AST/RecordLayout.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/AST/VTableBuilder.h"
#include "clang/Basic/SourceManager.h"
#include "clang/Sema/Sema.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/raw_ostream.h"

#include <algorithm>
#include <cstdlib>
#include <functional>

#include <algorithm>

using namespace clang;

namespace symcr_gen {

std::uint32_t TypeWalker::synthesizedPair(QualType Key, QualType Value,
                                          const WalkContext &C) {
  // The staged map element: std::pair<K, V> (symcr::ops::element_t), laid out
  // as the map's pair<const K, V>. Itanium layout of two members; checked by
  // static_assert in the home TU.
  Key = Key.getCanonicalType().getUnqualifiedType();
  Value = Value.getCanonicalType().getUnqualifiedType();
  TypeModel Model;
  Model.Kind = symcr::Kind::Struct;
  Model.Name = "std::pair<" + canonicalName(Key, C) + "," +
               canonicalName(Value, C) + ">";
  std::string KeySpelling = spelling(Key), ValueSpelling = spelling(Value);
  if (!KeySpelling.empty() && !ValueSpelling.empty())
    Model.Spelling = "::std::pair<" + KeySpelling + ", " + ValueSpelling + ">";
  Model.Accessible = accessible(Key) && accessible(Value);
  std::uint64_t KeySize = Context.getTypeSizeInChars(Key).getQuantity();
  std::uint64_t ValueSize = Context.getTypeSizeInChars(Value).getQuantity();
  std::uint64_t KeyAlign = Context.getTypeAlignInChars(Key).getQuantity();
  std::uint64_t ValueAlign = Context.getTypeAlignInChars(Value).getQuantity();
  std::uint64_t SecondOffset = llvm::alignTo(KeySize, ValueAlign);
  Model.Align = std::max(KeyAlign, ValueAlign);
  Model.Size = llvm::alignTo(SecondOffset + ValueSize, Model.Align);
  Model.NeedsLifecycle = true;
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  WalkContext First = C, Second = C;
  First.Path += ".first";
  Second.Path += ".second";
  FieldModel F1, F2;
  F1.Name = "first";
  F1.Type = walk(Key, First);
  F2.Name = "second";
  F2.Type = walk(Value, Second);
  F2.Offset = SecondOffset;
  if (F1.Type == symcr::kNoType || F2.Type == symcr::kNoType)
    return symcr::kNoType;
  Model.Fields = {F1, F2};
  store(Index, std::move(Model), C);
  return Index;
}

/// Finds the storage of element \p Wanted of a libstdc++ std::tuple: the
/// _Head_base<Wanted, T> base, holding the value in _M_head_impl or (empty T)
/// as its own base.
static bool findTupleElement(const ASTContext &Context, const CXXRecordDecl *RD,
                             unsigned Wanted, std::uint64_t Offset,
                             std::uint64_t &ElementOffset) {
  const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
  for (const CXXBaseSpecifier &Base : RD->bases()) {
    const CXXRecordDecl *BaseRD = Base.getType()->getAsCXXRecordDecl();
    if (!BaseRD || Base.isVirtual())
      continue;
    std::uint64_t BaseOffset =
        Offset + Layout.getBaseClassOffset(BaseRD).getQuantity();
    const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(BaseRD);
    if (Spec && Spec->getName() == "_Head_base" &&
        Spec->getTemplateArgs().size() >= 1 &&
        Spec->getTemplateArgs()[0].getKind() == TemplateArgument::Integral &&
        Spec->getTemplateArgs()[0].getAsIntegral() == Wanted) {
      for (const FieldDecl *F : Spec->fields())
        if (F->getName() == "_M_head_impl") {
          ElementOffset =
              BaseOffset + Context.getASTRecordLayout(Spec).getFieldOffset(
                               F->getFieldIndex()) /
                               8;
          return true;
        }
      ElementOffset = BaseOffset; // empty element stored as a base
      return true;
    }
    if (Spec && Spec->getName() == "_Tuple_impl" &&
        findTupleElement(Context, BaseRD, Wanted, BaseOffset, ElementOffset))
      return true;
  }
  return false;
}

std::uint32_t TypeWalker::stdRecord(QualType Type, const RecordDecl *RD,
                                    llvm::StringRef Name,
                                    const WalkContext &C) {
  const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(RD);
  auto Arg = [&](unsigned I) { return Spec->getTemplateArgs()[I].getAsType(); };
  TypeModel Model = describe(Type, C);
  bool Fresh;
  auto Reserve = [&] {
    std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
    Walked[{Type.getTypePtr(), false}] = Index;
    return Index;
  };
  auto Element = [&](QualType T, const char *Suffix) {
    WalkContext E = C;
    E.Path += Suffix;
    E.Shallow = false;
    E.AnonymousName.clear();
    return walk(T, E);
  };
  static const std::map<std::string, symcr::ContainerKind> Containers = {
      {"vector", symcr::ContainerKind::Vector},
      {"deque", symcr::ContainerKind::Deque},
      {"list", symcr::ContainerKind::List},
      {"forward_list", symcr::ContainerKind::ForwardList},
      {"set", symcr::ContainerKind::Set},
      {"multiset", symcr::ContainerKind::MultiSet},
      {"unordered_set", symcr::ContainerKind::UnorderedSet},
      {"unordered_multiset", symcr::ContainerKind::UnorderedMultiSet},
      {"map", symcr::ContainerKind::Map},
      {"multimap", symcr::ContainerKind::MultiMap},
      {"unordered_map", symcr::ContainerKind::UnorderedMap},
      {"unordered_multimap", symcr::ContainerKind::UnorderedMultiMap}};
  static const std::map<std::string, std::string> Unrestorable = {
      {"function", "a std::function holds code"},
      {"mutex", "a mutex is synchronisation state"},
      {"recursive_mutex", "a mutex is synchronisation state"},
      {"timed_mutex", "a mutex is synchronisation state"},
      {"shared_mutex", "a mutex is synchronisation state"},
      {"condition_variable", "a condition variable is synchronisation state"},
      {"thread", "a thread is process state"},
      {"jthread", "a thread is process state"},
      {"atomic", "atomics are synchronisation state"},
      {"weak_ptr", "a weak_ptr does not own its pointee"},
      {"basic_fstream", "a file stream is process state"},
      {"basic_ifstream", "a file stream is process state"},
      {"basic_ofstream", "a file stream is process state"},
      {"basic_filebuf", "a file stream is process state"},
      {"reference_wrapper", "a reference cannot be re-seated"},
      {"any", "its contained type is only known at run time"}};
  if (auto It = Unrestorable.find(Name.str()); It != Unrestorable.end())
    return fail(C, "'" + Model.Name + "'", It->second);
  if (Model.Spelling.empty())
    return fail(
        C, "'" + Model.Name + "'",
        "its operations must be instantiated by name, and one of its "
        "template arguments is an unnamed or local type; give that type a "
        "name at namespace or class scope");
  if (!Spec)
    goto Unsupported;
  if (Name == "basic_string") {
    Model.Kind = symcr::Kind::String;
    Model.Ops = OpsKind::String;
    std::uint32_t Index = Reserve();
    Model.Element = Element(Arg(0), "[]");
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (auto It = Containers.find(Name.str()); It != Containers.end()) {
    if (Name == "vector" && Arg(0)->isBooleanType())
      return fail(C, "'std::vector<bool>'",
                  "its elements are bits without addresses; use "
                  "std::vector<uint8_t> or "
                  "std::deque<bool>");
    Model.Kind = symcr::Kind::Container;
    Model.ContainerKind = static_cast<std::uint8_t>(It->second);
    Model.Ops = OpsKind::Container;
    std::uint32_t Index = Reserve();
    bool IsMap = Name.endswith("map");
    bool IsAssociative = IsMap || Name.endswith("set");
    if (IsMap) {
      WalkContext E = C;
      E.Path += "[]";
      E.Shallow = false;
      Model.Element = synthesizedPair(Arg(0), Arg(1), E);
    } else {
      Model.Element = Element(Arg(0), "[]");
    }
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    if (IsAssociative)
      Program.Types[Model.Element].NeedsLifecycle = true;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "array") {
    Model.Kind = symcr::Kind::Array;
    Model.Count = Spec->getTemplateArgs()[1].getAsIntegral().getZExtValue();
    std::uint32_t Index = Reserve();
    Model.Element = Element(Arg(0), "[]");
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "optional") {
    Model.Kind = symcr::Kind::Optional;
    Model.Ops = OpsKind::Optional;
    std::uint32_t Index = Reserve();
    Model.Element = Element(Arg(0), ".value");
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "variant") {
    Model.Kind = symcr::Kind::Variant;
    Model.Ops = OpsKind::Variant;
    std::uint32_t Index = Reserve();
    unsigned Alternative = 0;
    for (const TemplateArgument &A :
         Spec->getTemplateArgs()[0].pack_elements()) {
      std::string Suffix = "<" + std::to_string(Alternative++) + ">";
      std::uint32_t T = Element(A.getAsType(), Suffix.c_str());
      if (T == symcr::kNoType)
        return symcr::kNoType;
      Model.Alternatives.push_back(T);
    }
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "unique_ptr" || Name == "shared_ptr") {
    QualType Pointee = Arg(0);
    if (Pointee->isArrayType())
      return fail(C, "'" + Model.Name + "'",
                  "smart pointers to arrays are not supported");
    if (Name == "unique_ptr") {
      const auto *Deleter = Arg(1)->getAsCXXRecordDecl();
      if (!Deleter || Deleter->getName() != "default_delete")
        return fail(C, "'" + Model.Name + "'",
                    "a custom deleter cannot be recreated");
    }
    if (!checkPointee(Pointee, C,
                      Name == "unique_ptr" ? "unique_ptr" : "shared_ptr"))
      return symcr::kNoType;
    Model.Kind =
        Name == "unique_ptr" ? symcr::Kind::UniquePtr : symcr::Kind::SharedPtr;
    Model.Ops = Name == "unique_ptr" ? OpsKind::UniquePtr : OpsKind::SharedPtr;
    std::uint32_t Index = Reserve();
    Model.Element = walk(Pointee, intoPointee(C, Model.Name));
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "pair" || Name == "tuple" || Name == "monostate") {
    Model.Kind = symcr::Kind::Struct;
    std::uint32_t Index = Reserve();
    const auto *CRD = cast<CXXRecordDecl>(RD);
    if (Name == "pair") {
      const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
      for (const FieldDecl *F : RD->fields()) {
        FieldModel Field;
        Field.Name = F->getName().str();
        Field.Offset = Layout.getFieldOffset(F->getFieldIndex()) / 8;
        Field.Type = Element(F->getType(), ("." + Field.Name).c_str());
        if (Field.Type == symcr::kNoType)
          return symcr::kNoType;
        Model.Fields.push_back(Field);
      }
    } else if (Name == "tuple") {
      unsigned I = 0;
      for (const TemplateArgument &A :
           Spec->getTemplateArgs()[0].pack_elements()) {
        FieldModel Field;
        Field.Name = std::to_string(I);
        if (!findTupleElement(Context, CRD, I, 0, Field.Offset))
          return fail(C, "'" + Model.Name + "'",
                      "this standard library's std::tuple layout is not known "
                      "to symcr-gen");
        Field.Type = Element(A.getAsType(), ("." + Field.Name).c_str());
        if (Field.Type == symcr::kNoType)
          return symcr::kNoType;
        Model.Fields.push_back(Field);
        ++I;
      }
    }
    store(Index, std::move(Model), C);
    return Index;
  }
Unsupported:
  return fail(C, "'" + Model.Name + "'",
              "this standard library type is not supported (its members are "
              "implementation details)");
}

} // namespace symcr_gen
